/* The address rule both C transports share (posix_transport.c, win32_transport.c): an internal
 * header of the package's sources, not installed. Generated: do not edit. */
#ifndef MIPC_ADDRESS_H
#define MIPC_ADDRESS_H

#include <string.h>

/* HOST:PORT without "tcp:" (127.0.0.1:5000, localhost:5000, [::1]:5000): a numeric port, no '/'
 * or '\\' (a path, such as /dev/ttyUSB0 or \\.\COM10), an IPv6 host in brackets. The four
 * languages share the rule; such an address is refused with "did you mean tcp:...?" (on POSIX
 * unless a file of that name exists). */
static int mipc_looks_like_tcp(const char *address) {
    const char *colon = strrchr(address, ':');
    size_t host;
    if (colon == NULL || colon == address || colon[1] == '\0' ||
        strspn(colon + 1, "0123456789") != strlen(colon + 1) || strpbrk(address, "/\\") != NULL) {
        return 0;
    }
    host = (size_t)(colon - address);
    if (memchr(address, ':', host) == NULL) {
        return 1;
    }
    return address[0] == '[' && address[host - 1] == ']';
}

#endif /* MIPC_ADDRESS_H */
