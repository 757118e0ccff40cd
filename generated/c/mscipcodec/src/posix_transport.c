/* POSIX transports: TCP sockets and termios serial ports. Generated: do not edit. */
/* Built everywhere but Windows: there the file declares nothing else (win32_transport.c is the
 * transport), so a build that compiles every file of src/ works on any platform. */
#if !defined(_WIN32)
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 200809L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#if defined(__APPLE__) && !defined(_DARWIN_C_SOURCE)
#define _DARWIN_C_SOURCE
#endif
#include "mscipcodec/posix_transport.h"

#include "address.h"

#include <assert.h>
#include <errno.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#ifndef MSG_NOSIGNAL
#define MSG_NOSIGNAL 0
#endif

/* src into dst[cap], cut to fit (a reason is a short cause; a longer one loses its tail). Not
 * snprintf("%s"): gcc -O3 warns that it may truncate, which is the point here. */
static void copy_text(char *dst, size_t cap, const char *src) {
    size_t n = strlen(src);
    if (n >= cap) {
        n = cap - 1;
    }
    memcpy(dst, src, n);
    dst[n] = '\0';
}

static mscipc_status_t fail(mscipc_posix_t *t, const char *what, const char *detail) {
    snprintf(t->error, sizeof t->error, "%s%s%s", what, detail ? ": " : "", detail ? detail : "");
    copy_text(t->reason, sizeof t->reason, detail ? detail : what);
    if (t->fd >= 0) {
        close(t->fd);
        t->fd = -1;
    }
    return MSCIPC_ERR_INVALID;
}

static mscipc_status_t open_tcp(mscipc_posix_t *t, const char *address) {
    char host[256];
    const char *rest = address + 4;
    const char *port;
    struct addrinfo hints;
    struct addrinfo *res = NULL;
    struct addrinfo *ai;
    char what[320];
    int rc;
    size_t n;
    if (rest[0] == '[') {
        const char *end = strchr(rest, ']');
        if (end == NULL || end[1] != ':') {
            port = NULL;
        } else {
            n = (size_t)(end - rest - 1);
            if (n >= sizeof host) {
                port = NULL;
            } else {
                memcpy(host, rest + 1, n);
                host[n] = '\0';
                port = end + 2;
            }
        }
    } else {
        const char *colon = strrchr(rest, ':');
        n = colon ? (size_t)(colon - rest) : 0;
        if (colon == NULL || n >= sizeof host || memchr(rest, ':', n) != NULL) {
            port = NULL;
        } else {
            memcpy(host, rest, n);
            host[n] = '\0';
            port = colon + 1;
        }
    }
    if (port == NULL || host[0] == '\0' || port[0] == '\0' || strspn(port, "0123456789") != strlen(port) ||
        atol(port) < 1 || atol(port) > 65535) {
        snprintf(what, sizeof what, "bad TCP address '%s' (expected tcp:HOST:PORT)", address);
        return fail(t, what, NULL);
    }
    memset(&hints, 0, sizeof hints);
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    snprintf(what, sizeof what, "cannot connect to %s:%s", host, port);
    rc = getaddrinfo(host, port, &hints, &res);
    if (rc != 0) {
        return fail(t, what, gai_strerror(rc));
    }
    errno = 0;
    for (ai = res; ai != NULL; ai = ai->ai_next) {
        t->fd = socket(ai->ai_family, ai->ai_socktype, ai->ai_protocol);
        if (t->fd < 0) {
            continue;
        }
        if (connect(t->fd, ai->ai_addr, ai->ai_addrlen) == 0) {
            break;
        }
        close(t->fd);
        t->fd = -1;
    }
    freeaddrinfo(res);
    if (t->fd < 0) {
        return fail(t, what, strerror(errno ? errno : ECONNREFUSED));
    }
    {
        int one = 1;
        setsockopt(t->fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    }
    t->socket = true;
    return MSCIPC_OK;
}

static speed_t baud_constant(unsigned long baud, bool *ok) {
    *ok = true;
    switch (baud) {
    case 9600:
        return B9600;
    case 19200:
        return B19200;
    case 38400:
        return B38400;
    case 57600:
        return B57600;
    case 115200:
        return B115200;
    case 230400:
        return B230400;
#ifdef B460800
    case 460800:
        return B460800;
#endif
#ifdef B921600
    case 921600:
        return B921600;
#endif
#ifdef B1000000
    case 1000000:
        return B1000000;
#endif
#ifdef B1500000
    case 1500000:
        return B1500000;
#endif
#ifdef B2000000
    case 2000000:
        return B2000000;
#endif
#ifdef B3000000
    case 3000000:
        return B3000000;
#endif
    default:
        *ok = false;
        return B0;
    }
}

static mscipc_status_t open_serial(mscipc_posix_t *t, const char *path, unsigned long baud) {
    struct termios tio;
    bool ok;
    speed_t speed = baud_constant(baud, &ok);
    char what[320];
    snprintf(what, sizeof what, "cannot open %s at %lu baud", path, baud);
    if (!ok) {
        char why[64];
        snprintf(why, sizeof why, "unsupported baud rate %lu", baud);
        return fail(t, what, why);
    }
    t->fd = open(path, O_RDWR | O_NOCTTY);
    if (t->fd < 0) {
        return fail(t, what, strerror(errno));
    }
    if (tcgetattr(t->fd, &tio) != 0) {
        return fail(t, what, strerror(errno));
    }
    tio.c_iflag &=
        (tcflag_t) ~(IGNBRK | BRKINT | PARMRK | ISTRIP | INLCR | IGNCR | ICRNL | IXON | IXOFF | IXANY);
    tio.c_oflag &= (tcflag_t)~OPOST;
    tio.c_lflag &= (tcflag_t) ~(ECHO | ECHONL | ICANON | ISIG | IEXTEN);
    tio.c_cflag &= (tcflag_t) ~(CSIZE | PARENB | CSTOPB);
    tio.c_cflag |= (tcflag_t)(CS8 | CREAD | CLOCAL);
    tio.c_cc[VMIN] = 0;
    tio.c_cc[VTIME] = 0;
    if (cfsetispeed(&tio, speed) != 0 || cfsetospeed(&tio, speed) != 0 ||
        tcsetattr(t->fd, TCSANOW, &tio) != 0) {
        return fail(t, what, strerror(errno));
    }
    t->socket = false;
    return MSCIPC_OK;
}

mscipc_status_t mscipc_posix_open(mscipc_posix_t *posix, const char *address, unsigned long baud) {
    assert(posix != NULL);
    assert(address != NULL);
    memset(posix, 0, sizeof *posix);
    posix->fd = -1;
    posix->baud = baud;
    if (strlen(address) >= sizeof posix->address) {
        return fail(posix, "address too long", NULL);
    }
    memcpy(posix->address, address, strlen(address) + 1);
    if (address[0] == '\0') {
        return fail(posix, "empty address (expected tcp:HOST:PORT or a serial port path)", NULL);
    }
    if (strncmp(address, "tcp:", 4) == 0) {
        return open_tcp(posix, address);
    }
    if (mscipc_looks_like_tcp(address) && access(address, F_OK) != 0) {
        snprintf(posix->error, sizeof posix->error, "'%s' is not a serial port: did you mean tcp:%s?",
                 address, address);
        copy_text(posix->reason, sizeof posix->reason, "not a serial port");
        return MSCIPC_ERR_INVALID;
    }
    return open_serial(posix, address, baud);
}

/* A failed read or write: the message and the bare reason (the link's "port lost (REASON)"). */
static int lost(mscipc_posix_t *t, const char *what, const char *reason) {
    snprintf(t->error, sizeof t->error, "%s: %s", what, reason);
    copy_text(t->reason, sizeof t->reason, reason);
    return -1;
}

static int posix_read(void *ctx, uint8_t *buf, size_t cap, uint32_t timeout_ms) {
    mscipc_posix_t *t = (mscipc_posix_t *)ctx;
    struct pollfd p;
    ssize_t n;
    int rc;
    if (t->fd < 0) {
        return lost(t, "receive failed", "the port is closed");
    }
    p.fd = t->fd;
    p.events = POLLIN;
    p.revents = 0;
    rc = poll(&p, 1, timeout_ms > 0x7fffffffu ? 0x7fffffff : (int)timeout_ms);
    if (rc < 0) {
        if (errno == EINTR) {
            return 0;
        }
        return lost(t, "receive failed", strerror(errno));
    }
    if (rc == 0) {
        return 0;
    }
    n = t->socket ? recv(t->fd, buf, cap, 0) : read(t->fd, buf, cap);
    if (n < 0) {
        if (errno == EINTR || errno == EAGAIN) {
            return 0;
        }
        return lost(t, "receive failed", strerror(errno));
    }
    if (n == 0) {
        if (!t->socket && (p.revents & POLLHUP) == 0) {
            return 0;
        }
        return lost(t, "receive failed", "end of file");
    }
    return (int)n;
}

static int posix_write(void *ctx, const uint8_t *data, size_t len) {
    mscipc_posix_t *t = (mscipc_posix_t *)ctx;
    if (t->fd < 0) {
        return lost(t, "send failed", "the port is closed");
    }
    while (len > 0) {
        ssize_t n = t->socket ? send(t->fd, data, len, MSG_NOSIGNAL) : write(t->fd, data, len);
        if (n < 0) {
            if (errno == EINTR) {
                continue;
            }
            return lost(t, "send failed", strerror(errno));
        }
        data += n;
        len -= (size_t)n;
    }
    return 0;
}

static uint64_t posix_now_ms(void *ctx) {
    struct timespec ts;
    (void)ctx;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000u + (uint64_t)ts.tv_nsec / 1000000u;
}

void mscipc_posix_transport(mscipc_posix_t *posix, mscipc_transport_t *out) {
    assert(posix != NULL);
    assert(out != NULL);
    out->ctx = posix;
    out->read = posix_read;
    out->write = posix_write;
    out->now_ms = posix_now_ms;
}

void mscipc_posix_close(mscipc_posix_t *posix) {
    assert(posix != NULL);
    if (posix->fd >= 0) {
        close(posix->fd);
        posix->fd = -1;
    }
}

/* ------------------------------------------------------------------ getting through (link.h) */
static int posix_flush(void *ctx) {
    mscipc_posix_t *t = (mscipc_posix_t *)ctx;
    if (t->fd < 0) {
        return -1;
    }
    if (!t->socket) {
        return tcflush(t->fd, TCIFLUSH) == 0 ? 0 : -1;
    }
    /* a socket: read what is there without waiting, at most 1 MiB (under a flood there is always
       more: the flush must end) */
    for (int k = 0; k < 256; k++) {
        uint8_t buf[4096];
        ssize_t n = recv(t->fd, buf, sizeof buf, MSG_DONTWAIT);
        if (n <= 0) {
            return n == 0 ? -1 : 0;
        }
    }
    return 0;
}

static int posix_set_baud(void *ctx, uint32_t baud) {
    mscipc_posix_t *t = (mscipc_posix_t *)ctx;
    struct termios tio;
    bool ok;
    speed_t speed = baud_constant(baud, &ok);
    if (!ok) {
        snprintf(t->reason, sizeof t->reason, "unsupported baud rate %lu", (unsigned long)baud);
        return -1;
    }
    if (t->fd < 0 || tcgetattr(t->fd, &tio) != 0 || cfsetispeed(&tio, speed) != 0 ||
        cfsetospeed(&tio, speed) != 0 || tcsetattr(t->fd, TCSANOW, &tio) != 0) {
        copy_text(t->reason, sizeof t->reason, t->fd < 0 ? "the port is closed" : strerror(errno));
        return -1;
    }
    t->baud = baud;
    return 0;
}

static int posix_reopen(void *ctx) {
    mscipc_posix_t *t = (mscipc_posix_t *)ctx;
    mscipc_posix_t fresh;
    if (t->fd >= 0) {
        close(t->fd);
        t->fd = -1;
    }
    if (mscipc_posix_open(&fresh, t->address, t->baud) != MSCIPC_OK) {
        memcpy(t->error, fresh.error, sizeof t->error);
        memcpy(t->reason, fresh.reason, sizeof t->reason);
        return -1;
    }
    *t = fresh;
    return 0;
}

static const char *posix_address(void *ctx) {
    return ((const mscipc_posix_t *)ctx)->address;
}

static const char *posix_reason(void *ctx) {
    return ((const mscipc_posix_t *)ctx)->reason;
}

static void posix_sleep(void *ctx, uint32_t ms) {
    struct timespec ts;
    (void)ctx;
    ts.tv_sec = (time_t)(ms / 1000u);
    ts.tv_nsec = (long)(ms % 1000u) * 1000000L;
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {
    }
}

void mscipc_posix_port(mscipc_posix_t *posix, mscipc_port_t *out) {
    assert(posix != NULL);
    assert(out != NULL);
    memset(out, 0, sizeof *out);
    out->ctx = posix;
    out->flush = posix_flush;
    out->set_baud = posix->socket ? NULL : posix_set_baud;
    out->reopen = posix_reopen;
    out->address = posix_address;
    out->reason = posix_reason;
    out->sleep_ms = posix_sleep;
    out->baud = posix->socket ? 0u : (uint32_t)posix->baud;
}

#else
typedef int mscipc_posix_transport_not_built; /* ISO C: a translation unit declares something */
#endif
