/* Win32 transports for the blocking session API (codec/link.h), the Windows counterpart of
 * codec/posix_transport.h with the same operations: TCP through Winsock 2 (IPv4, IPv6 in brackets,
 * host names) and serial ports (COM ports: 8N1, binary, no flow control, the baud rate as a number
 * of bit/s set in the port's DCB; read timeouts through COMMTIMEOUTS, input flush by PurgeComm).
 * Not part of the freestanding core: a separate library (CMake option <PKG>_WIN32, ON on Windows;
 * it links ws2_32). This header does not include <windows.h>. */
#ifndef CODEC_WIN32_TRANSPORT_H
#define CODEC_WIN32_TRANSPORT_H

#include <stdint.h>

#include "codec/link.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    void *handle;      /* the serial port's HANDLE; NULL when closed or a socket */
    uintptr_t sock;    /* the socket (a Winsock SOCKET); 0 when none */
    bool socket;       /* TCP (sock) rather than a serial port (handle) */
    bool winsock;      /* WSAStartup succeeded (WSACleanup at close) */
    uint32_t timeout;  /* the read timeout the port's COMMTIMEOUTS hold now, in ms (+1; 0: not set) */
    char error[400];   /* the last failure */
    char reason[128];  /* its cause alone (the system's message; the link's "port lost (...)") */
    char address[256]; /* the address opened (reopened after a loss) */
    unsigned long baud;
} codec_win32_t;

/**
 * Opens ADDRESS: "tcp:HOST:PORT" (HOST a name, an IPv4 address or an IPv6 address in brackets,
 * "tcp:[::1]:5000") or a serial port: "COM3", "COM10" (opened as "\\.\COM10", the name every COM
 * port can be opened by; "COM1" to "COM9" need no prefix but take it too) or a device path given
 * whole ("\\.\COM10"), opened at `baud`. Returns CODEC_OK, or CODEC_ERR_INVALID with the reason in
 * win32->error ("bad TCP address ...", "cannot connect to HOST:PORT: ...", "cannot open COM3 at N
 * baud: ...").
 */
codec_status_t codec_win32_open(codec_win32_t *win32, const char *address, unsigned long baud);
/** The transport callbacks over an open win32 transport. */
void codec_win32_transport(codec_win32_t *win32, codec_transport_t *out);
void codec_win32_close(codec_win32_t *win32);
/** The port operations of getting through (codec_link_attach): input flush (PurgeComm, or a
 * socket drained), the baud rate (the DCB; none over TCP), reopening the same address, the pause
 * between attempts (Sleep). */
void codec_win32_port(codec_win32_t *win32, codec_port_t *out);

#ifdef __cplusplus
}
#endif

#endif
