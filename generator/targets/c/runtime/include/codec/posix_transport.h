/* POSIX transports for the blocking session API (codec/link.h): TCP (IPv4, IPv6 in brackets,
 * host names) and serial ports (termios, 8N1, raw, the baud rate as a number of bit/s). Not part of
 * the freestanding core: a separate library (CMake option CODEC_POSIX). */
#ifndef CODEC_POSIX_TRANSPORT_H
#define CODEC_POSIX_TRANSPORT_H

#include "codec/link.h"

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
} codec_posix_t;

/**
 * Opens ADDRESS: "tcp:HOST:PORT" (HOST a name, an IPv4 address or an IPv6 address in brackets,
 * "tcp:[::1]:5000") or a serial port path ("/dev/ttyUSB0") opened at `baud`. Returns CODEC_OK, or
 * CODEC_ERR_INVALID with the reason in posix->error ("bad TCP address ...", "cannot connect to
 * HOST:PORT: ...", "cannot open PATH at N baud: ...", "unsupported baud rate N").
 */
codec_status_t codec_posix_open(codec_posix_t *posix, const char *address, unsigned long baud);
/** The transport callbacks over an open posix transport. */
void codec_posix_transport(codec_posix_t *posix, codec_transport_t *out);
void codec_posix_close(codec_posix_t *posix);
/** The port operations of getting through (codec_link_attach): input flush (tcflush, or a socket
 * drained), the baud rate (termios; none over TCP), reopening the same address, the pause between
 * attempts. */
void codec_posix_port(codec_posix_t *posix, codec_port_t *out);

#ifdef __cplusplus
}
#endif

#endif
