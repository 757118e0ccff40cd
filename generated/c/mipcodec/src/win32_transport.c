/* Win32 transports: Winsock 2 TCP sockets and COM serial ports (mipcodec/win32_transport.h).
 * Generated: do not edit. */
/* Built for Windows only: elsewhere the file declares nothing else, so a build that compiles every
 * file of src/ (a vendored copy, the big-endian and fuzz builds) works on any platform; the POSIX
 * transport (posix_transport.c) is the one there. */
#if defined(_WIN32)
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#ifndef _WIN32_WINNT
#define _WIN32_WINNT 0x0600 /* Vista: getaddrinfo, GetTickCount64 */
#endif
#include "mipcodec/win32_transport.h"

#include "address.h"

#include <winsock2.h>
#include <ws2tcpip.h>
#include <windows.h>

#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NO_SOCKET ((uintptr_t)0)

/* src into dst[cap], cut to fit (a reason is a short cause; a longer one loses its tail). */
static void copy_text(char *dst, size_t cap, const char *src) {
    size_t n = strlen(src);
    if (n >= cap) {
        n = cap - 1;
    }
    memcpy(dst, src, n);
    dst[n] = '\0';
}

/* The system's message for an error code (GetLastError, WSAGetLastError or a getaddrinfo
 * result), without its trailing period and line end; "error N" when the system has none. */
static void system_text(DWORD code, char *out, size_t cap) {
    DWORD n = FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, NULL, code,
                             MAKELANGID(LANG_ENGLISH, SUBLANG_ENGLISH_US), out, (DWORD)cap, NULL);
    if (n == 0) {
        n = FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, NULL, code, 0, out,
                           (DWORD)cap, NULL);
    }
    if (n == 0) {
        snprintf(out, cap, "error %lu", (unsigned long)code);
        return;
    }
    while (n > 0 && (out[n - 1] == '\r' || out[n - 1] == '\n' || out[n - 1] == ' ' || out[n - 1] == '.')) {
        out[--n] = '\0';
    }
}

static void close_all(mipc_win32_t *t) {
    if (t->sock != NO_SOCKET) {
        closesocket((SOCKET)t->sock);
        t->sock = NO_SOCKET;
    }
    if (t->handle != NULL) {
        CloseHandle((HANDLE)t->handle);
        t->handle = NULL;
    }
    if (t->winsock) {
        WSACleanup();
        t->winsock = false;
    }
}

static mipc_status_t fail(mipc_win32_t *t, const char *what, const char *detail) {
    snprintf(t->error, sizeof t->error, "%s%s%s", what, detail ? ": " : "", detail ? detail : "");
    copy_text(t->reason, sizeof t->reason, detail ? detail : what);
    close_all(t);
    return MIPC_ERR_INVALID;
}

static mipc_status_t fail_code(mipc_win32_t *t, const char *what, DWORD code) {
    char text[200];
    system_text(code, text, sizeof text);
    return fail(t, what, text);
}

static mipc_status_t open_tcp(mipc_win32_t *t, const char *address) {
    char host[256];
    const char *rest = address + 4;
    const char *port;
    struct addrinfo hints;
    struct addrinfo *res = NULL;
    struct addrinfo *ai;
    char what[320];
    WSADATA wsa;
    int rc;
    int last = 0;
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
    snprintf(what, sizeof what, "cannot connect to %s:%s", host, port);
    rc = WSAStartup(MAKEWORD(2, 2), &wsa);
    if (rc != 0) {
        return fail_code(t, what, (DWORD)rc);
    }
    t->winsock = true;
    memset(&hints, 0, sizeof hints);
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_protocol = IPPROTO_TCP;
    rc = getaddrinfo(host, port, &hints, &res);
    if (rc != 0) {
        return fail_code(t, what, (DWORD)rc);
    }
    for (ai = res; ai != NULL; ai = ai->ai_next) {
        SOCKET s = socket(ai->ai_family, ai->ai_socktype, ai->ai_protocol);
        if (s == INVALID_SOCKET) {
            last = WSAGetLastError();
            continue;
        }
        if (connect(s, ai->ai_addr, (int)ai->ai_addrlen) == 0) {
            t->sock = (uintptr_t)s;
            break;
        }
        last = WSAGetLastError();
        closesocket(s);
    }
    freeaddrinfo(res);
    if (t->sock == NO_SOCKET) {
        return fail_code(t, what, (DWORD)(last ? last : WSAECONNREFUSED));
    }
    {
        BOOL one = TRUE;
        setsockopt((SOCKET)t->sock, IPPROTO_TCP, TCP_NODELAY, (const char *)&one, (int)sizeof one);
    }
    t->socket = true;
    return MIPC_OK;
}

/* The device name a serial address is opened by: "COMn" (any case) becomes "\\.\COMn", which
 * every COM port answers to (COM10 and above only to it); anything else is used as given. */
static void serial_device_name(const char *address, char *out, size_t cap) {
    if ((address[0] == 'C' || address[0] == 'c') && (address[1] == 'O' || address[1] == 'o') &&
        (address[2] == 'M' || address[2] == 'm') && address[3] != '\0' &&
        strspn(address + 3, "0123456789") == strlen(address + 3)) {
        snprintf(out, cap, "\\\\.\\%s", address);
    } else {
        copy_text(out, cap, address);
    }
}

/* The port's line settings: `baud`, 8 data bits, no parity, one stop bit, binary, no flow control
 * (hardware or XON/XOFF), DTR and RTS on, no abort on errors. */
static BOOL set_line(HANDLE h, unsigned long baud) {
    DCB dcb;
    memset(&dcb, 0, sizeof dcb);
    dcb.DCBlength = sizeof dcb;
    if (!GetCommState(h, &dcb)) {
        return FALSE;
    }
    dcb.BaudRate = (DWORD)baud;
    dcb.ByteSize = 8;
    dcb.Parity = NOPARITY;
    dcb.StopBits = ONESTOPBIT;
    dcb.fBinary = TRUE;
    dcb.fParity = FALSE;
    dcb.fOutxCtsFlow = FALSE;
    dcb.fOutxDsrFlow = FALSE;
    dcb.fDtrControl = DTR_CONTROL_ENABLE;
    dcb.fDsrSensitivity = FALSE;
    dcb.fOutX = FALSE;
    dcb.fInX = FALSE;
    dcb.fErrorChar = FALSE;
    dcb.fNull = FALSE;
    dcb.fRtsControl = RTS_CONTROL_ENABLE;
    dcb.fAbortOnError = FALSE;
    return SetCommState(h, &dcb);
}

static mipc_status_t open_serial(mipc_win32_t *t, const char *address, unsigned long baud) {
    char name[280];
    char what[320];
    HANDLE h;
    snprintf(what, sizeof what, "cannot open %s at %lu baud", address, baud);
    if (baud == 0 || baud > 0xffffffffUL) {
        char why[64];
        snprintf(why, sizeof why, "unsupported baud rate %lu", baud);
        return fail(t, what, why);
    }
    serial_device_name(address, name, sizeof name);
    h = CreateFileA(name, GENERIC_READ | GENERIC_WRITE, 0, NULL, OPEN_EXISTING, FILE_ATTRIBUTE_NORMAL, NULL);
    if (h == INVALID_HANDLE_VALUE) {
        return fail_code(t, what, GetLastError());
    }
    t->handle = (void *)h;
    if (!set_line(h, baud)) {
        return fail_code(t, what, GetLastError());
    }
    PurgeComm(h, PURGE_RXCLEAR | PURGE_TXCLEAR);
    t->timeout = 0;
    t->socket = false;
    return MIPC_OK;
}

mipc_status_t mipc_win32_open(mipc_win32_t *win32, const char *address, unsigned long baud) {
    assert(win32 != NULL);
    assert(address != NULL);
    memset(win32, 0, sizeof *win32);
    win32->baud = baud;
    if (strlen(address) >= sizeof win32->address) {
        return fail(win32, "address too long", NULL);
    }
    memcpy(win32->address, address, strlen(address) + 1);
    if (address[0] == '\0') {
        return fail(win32, "empty address (expected tcp:HOST:PORT or a serial port such as COM3)", NULL);
    }
    if (strncmp(address, "tcp:", 4) == 0) {
        return open_tcp(win32, address);
    }
    if (mipc_looks_like_tcp(address)) {
        snprintf(win32->error, sizeof win32->error, "'%s' is not a serial port: did you mean tcp:%s?",
                 address, address);
        copy_text(win32->reason, sizeof win32->reason, "not a serial port");
        return MIPC_ERR_INVALID;
    }
    return open_serial(win32, address, baud);
}

/* A failed read or write: the message and the bare reason (the link's "port lost (REASON)"). */
static int lost(mipc_win32_t *t, const char *what, const char *reason) {
    snprintf(t->error, sizeof t->error, "%s: %s", what, reason);
    copy_text(t->reason, sizeof t->reason, reason);
    return -1;
}

static int lost_code(mipc_win32_t *t, const char *what, DWORD code) {
    char text[200];
    system_text(code, text, sizeof text);
    return lost(t, what, text);
}

static int socket_read(mipc_win32_t *t, uint8_t *buf, size_t cap, uint32_t timeout_ms) {
    SOCKET s = (SOCKET)t->sock;
    fd_set readable;
    struct timeval tv;
    int rc;
    FD_ZERO(&readable);
    FD_SET(s, &readable);
    tv.tv_sec = (long)(timeout_ms / 1000u);
    tv.tv_usec = (long)(timeout_ms % 1000u) * 1000L;
    rc = select(0, &readable, NULL, NULL, &tv);
    if (rc == SOCKET_ERROR) {
        return lost_code(t, "receive failed", (DWORD)WSAGetLastError());
    }
    if (rc == 0) {
        return 0;
    }
    rc = recv(s, (char *)buf, cap > 0x7fffffff ? 0x7fffffff : (int)cap, 0);
    if (rc == SOCKET_ERROR) {
        int err = WSAGetLastError();
        if (err == WSAEWOULDBLOCK || err == WSAEINTR) {
            return 0;
        }
        return lost_code(t, "receive failed", (DWORD)err);
    }
    if (rc == 0) {
        return lost(t, "receive failed", "end of file");
    }
    return rc;
}

/* ReadFile returns as soon as a byte is there, or after timeout_ms with none (the COMMTIMEOUTS
 * rule of MAXDWORD interval and multiplier with a constant; a zero timeout returns at once). */
static int serial_read(mipc_win32_t *t, uint8_t *buf, size_t cap, uint32_t timeout_ms) {
    HANDLE h = (HANDLE)t->handle;
    DWORD got = 0;
    uint32_t wait = timeout_ms > 0xfffffff0u ? 0xfffffff0u : timeout_ms;
    if (t->timeout != wait + 1u) {
        COMMTIMEOUTS to;
        memset(&to, 0, sizeof to);
        to.ReadIntervalTimeout = MAXDWORD;
        to.ReadTotalTimeoutMultiplier = wait == 0 ? 0 : MAXDWORD;
        to.ReadTotalTimeoutConstant = (DWORD)wait;
        if (!SetCommTimeouts(h, &to)) {
            return lost_code(t, "receive failed", GetLastError());
        }
        t->timeout = wait + 1u;
    }
    if (!ReadFile(h, buf, cap > 0x7fffffff ? 0x7fffffffUL : (DWORD)cap, &got, NULL)) {
        return lost_code(t, "receive failed", GetLastError());
    }
    return (int)got;
}

static int win32_read(void *ctx, uint8_t *buf, size_t cap, uint32_t timeout_ms) {
    mipc_win32_t *t = (mipc_win32_t *)ctx;
    if (t->socket ? t->sock == NO_SOCKET : t->handle == NULL) {
        return lost(t, "receive failed", "the port is closed");
    }
    return t->socket ? socket_read(t, buf, cap, timeout_ms) : serial_read(t, buf, cap, timeout_ms);
}

static int win32_write(void *ctx, const uint8_t *data, size_t len) {
    mipc_win32_t *t = (mipc_win32_t *)ctx;
    if (t->socket ? t->sock == NO_SOCKET : t->handle == NULL) {
        return lost(t, "send failed", "the port is closed");
    }
    while (len > 0) {
        size_t chunk = len > 0x10000u ? 0x10000u : len;
        size_t done;
        if (t->socket) {
            int n = send((SOCKET)t->sock, (const char *)data, (int)chunk, 0);
            if (n == SOCKET_ERROR) {
                return lost_code(t, "send failed", (DWORD)WSAGetLastError());
            }
            done = (size_t)n;
        } else {
            DWORD n = 0;
            if (!WriteFile((HANDLE)t->handle, data, (DWORD)chunk, &n, NULL)) {
                return lost_code(t, "send failed", GetLastError());
            }
            if (n == 0) {
                return lost(t, "send failed", "the port took no bytes");
            }
            done = (size_t)n;
        }
        data += done;
        len -= done;
    }
    return 0;
}

static uint64_t win32_now_ms(void *ctx) {
    (void)ctx;
    return (uint64_t)GetTickCount64();
}

void mipc_win32_transport(mipc_win32_t *win32, mipc_transport_t *out) {
    assert(win32 != NULL);
    assert(out != NULL);
    out->ctx = win32;
    out->read = win32_read;
    out->write = win32_write;
    out->now_ms = win32_now_ms;
}

void mipc_win32_close(mipc_win32_t *win32) {
    assert(win32 != NULL);
    close_all(win32);
}

/* ------------------------------------------------------------------ getting through (link.h) */
static int win32_flush(void *ctx) {
    mipc_win32_t *t = (mipc_win32_t *)ctx;
    if (!t->socket) {
        return t->handle != NULL && PurgeComm((HANDLE)t->handle, PURGE_RXCLEAR | PURGE_RXABORT) ? 0 : -1;
    }
    if (t->sock == NO_SOCKET) {
        return -1;
    }
    for (;;) { /* a socket: read what is there without waiting */
        char buf[512];
        fd_set readable;
        struct timeval tv = {0, 0};
        int n;
        FD_ZERO(&readable);
        FD_SET((SOCKET)t->sock, &readable);
        if (select(0, &readable, NULL, NULL, &tv) <= 0) {
            return 0;
        }
        n = recv((SOCKET)t->sock, buf, (int)sizeof buf, 0);
        if (n <= 0) {
            return -1;
        }
    }
}

static int win32_set_baud(void *ctx, uint32_t baud) {
    mipc_win32_t *t = (mipc_win32_t *)ctx;
    if (t->handle == NULL) {
        copy_text(t->reason, sizeof t->reason, "the port is closed");
        return -1;
    }
    if (baud == 0 || !set_line((HANDLE)t->handle, baud)) {
        char text[200];
        system_text(GetLastError(), text, sizeof text);
        snprintf(t->reason, sizeof t->reason, "cannot set %lu baud: %s", (unsigned long)baud, text);
        return -1;
    }
    t->baud = baud;
    return 0;
}

static int win32_reopen(void *ctx) {
    mipc_win32_t *t = (mipc_win32_t *)ctx;
    mipc_win32_t fresh;
    close_all(t);
    if (mipc_win32_open(&fresh, t->address, t->baud) != MIPC_OK) {
        memcpy(t->error, fresh.error, sizeof t->error);
        memcpy(t->reason, fresh.reason, sizeof t->reason);
        return -1;
    }
    *t = fresh;
    return 0;
}

static const char *win32_address(void *ctx) {
    return ((const mipc_win32_t *)ctx)->address;
}

static const char *win32_reason(void *ctx) {
    return ((const mipc_win32_t *)ctx)->reason;
}

static void win32_sleep(void *ctx, uint32_t ms) {
    (void)ctx;
    Sleep((DWORD)ms);
}

void mipc_win32_port(mipc_win32_t *win32, mipc_port_t *out) {
    assert(win32 != NULL);
    assert(out != NULL);
    memset(out, 0, sizeof *out);
    out->ctx = win32;
    out->flush = win32_flush;
    out->set_baud = win32->socket ? NULL : win32_set_baud;
    out->reopen = win32_reopen;
    out->address = win32_address;
    out->reason = win32_reason;
    out->sleep_ms = win32_sleep;
    out->baud = win32->socket ? 0u : (uint32_t)win32->baud;
}

#else
typedef int mipc_win32_transport_not_built; /* ISO C: a translation unit declares something */
#endif
