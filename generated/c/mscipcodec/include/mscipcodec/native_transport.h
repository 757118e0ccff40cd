/* The transports of the platform the program is built for, under one set of names, for programs
 * that run on both POSIX systems and Windows (the session tool): mscipc_native_t, mscipc_native_open,
 * mscipc_native_transport, mscipc_native_close and mscipc_native_port are the POSIX transports of
 * mscipcodec/posix_transport.h (CMake option <PKG>_POSIX) on Unix and the Win32 ones of
 * mscipcodec/win32_transport.h (<PKG>_WIN32) on Windows. The addresses are the same but for
 * the serial port's name ("/dev/ttyUSB0", "COM3"). Generated: do not edit. */
#ifndef MSCIPC_NATIVE_TRANSPORT_H
#define MSCIPC_NATIVE_TRANSPORT_H

#ifdef _WIN32
#include "mscipcodec/win32_transport.h"
typedef mscipc_win32_t mscipc_native_t;
#define MSCIPC_NATIVE(name) mscipc_win32_##name
#else
#include "mscipcodec/posix_transport.h"
typedef mscipc_posix_t mscipc_native_t;
#define MSCIPC_NATIVE(name) mscipc_posix_##name
#endif

static inline mscipc_status_t mscipc_native_open(mscipc_native_t *t, const char *address,
                                                 unsigned long baud) {
    return MSCIPC_NATIVE(open)(t, address, baud);
}
static inline void mscipc_native_transport(mscipc_native_t *t, mscipc_transport_t *out) {
    MSCIPC_NATIVE(transport)(t, out);
}
static inline void mscipc_native_close(mscipc_native_t *t) {
    MSCIPC_NATIVE(close)(t);
}
static inline void mscipc_native_port(mscipc_native_t *t, mscipc_port_t *out) {
    MSCIPC_NATIVE(port)(t, out);
}

#endif
