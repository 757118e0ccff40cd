/* POSIX transports for the blocking session API (democodec/link.h): TCP (IPv4, IPv6 in brackets,
 * host names) and serial ports (termios, 8N1, raw, the baud rate as a number of bit/s). Not part of
 * the freestanding core: a separate library (CMake option DEMOC_POSIX). Generated: do not edit. */
#ifndef DEMOC_POSIX_TRANSPORT_H
#define DEMOC_POSIX_TRANSPORT_H

#include "democodec/link.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    int fd;
    bool socket;
    char error[400]; /* the last failure */
} democ_posix_t;

/**
 * Opens ADDRESS: "tcp:HOST:PORT" (HOST a name, an IPv4 address or an IPv6 address in brackets,
 * "tcp:[::1]:5000") or a serial port path ("/dev/ttyUSB0") opened at `baud`. Returns DEMOC_OK, or
 * DEMOC_ERR_INVALID with the reason in posix->error ("bad TCP address ...", "cannot connect to
 * HOST:PORT: ...", "cannot open PATH at N baud: ...", "unsupported baud rate N").
 */
democ_status_t democ_posix_open(democ_posix_t *posix, const char *address, unsigned long baud);
/** The transport callbacks over an open posix transport. */
void democ_posix_transport(democ_posix_t *posix, democ_transport_t *out);
void democ_posix_close(democ_posix_t *posix);

#ifdef __cplusplus
}
#endif

#endif
