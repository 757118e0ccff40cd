/* The transports of the platform the program is built for, under one set of names, for programs
 * that run on both POSIX systems and Windows (the session tool): mipc_native_t, mipc_native_open,
 * mipc_native_transport, mipc_native_close and mipc_native_port are the POSIX transports of
 * mipcodec/posix_transport.h (CMake option <PKG>_POSIX) on Unix and the Win32 ones of
 * mipcodec/win32_transport.h (<PKG>_WIN32) on Windows. The addresses are the same but for
 * the serial port's name ("/dev/ttyUSB0", "COM3"). Generated: do not edit. */
#ifndef MIPC_NATIVE_TRANSPORT_H
#define MIPC_NATIVE_TRANSPORT_H

#ifdef _WIN32
#include "mipcodec/win32_transport.h"
typedef mipc_win32_t mipc_native_t;
#define MIPC_NATIVE(name) mipc_win32_##name
#else
#include "mipcodec/posix_transport.h"
typedef mipc_posix_t mipc_native_t;
#define MIPC_NATIVE(name) mipc_posix_##name
#endif

static inline mipc_status_t mipc_native_open(mipc_native_t *t, const char *address, unsigned long baud) {
    return MIPC_NATIVE(open)(t, address, baud);
}
static inline void mipc_native_transport(mipc_native_t *t, mipc_transport_t *out) {
    MIPC_NATIVE(transport)(t, out);
}
static inline void mipc_native_close(mipc_native_t *t) {
    MIPC_NATIVE(close)(t);
}
static inline void mipc_native_port(mipc_native_t *t, mipc_port_t *out) {
    MIPC_NATIVE(port)(t, out);
}

#endif
