/* POSIX transports for the blocking session API (mscipcodec/link.h): TCP (IPv4, IPv6 in brackets,
 * host names) and serial ports (termios, 8N1, raw, the baud rate as a number of bit/s). Not part of
 * the freestanding core: a separate library (CMake option MSCIPC_POSIX). Generated: do not edit. */
#ifndef MSCIPC_POSIX_TRANSPORT_H
#define MSCIPC_POSIX_TRANSPORT_H

#include "mscipcodec/link.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    int fd;
    bool socket;
    char error[400];   /* the last failure */
    char reason[128];  /* its cause alone ("Input/output error"; the link's "port lost (...)") */
    char address[256]; /* the address opened (reopened after a loss) */
    unsigned long baud;
} mscipc_posix_t;

/**
 * Opens ADDRESS: "tcp:HOST:PORT" (HOST a name, an IPv4 address or an IPv6 address in brackets,
 * "tcp:[::1]:5000") or a serial port path ("/dev/ttyUSB0") opened at `baud`. Returns MSCIPC_OK, or
 * MSCIPC_ERR_INVALID with the reason in posix->error ("bad TCP address ...", "cannot connect to
 * HOST:PORT: ...", "cannot open PATH at N baud: ...", "unsupported baud rate N").
 */
mscipc_status_t mscipc_posix_open(mscipc_posix_t *posix, const char *address, unsigned long baud);
/** The transport callbacks over an open posix transport. */
void mscipc_posix_transport(mscipc_posix_t *posix, mscipc_transport_t *out);
void mscipc_posix_close(mscipc_posix_t *posix);
/** The port operations of getting through (mscipc_link_attach): input flush (tcflush, or a socket
 * drained), the baud rate (termios; none over TCP), reopening the same address, the pause between
 * attempts. */
void mscipc_posix_port(mscipc_posix_t *posix, mscipc_port_t *out);

#ifdef __cplusplus
}
#endif

#endif
