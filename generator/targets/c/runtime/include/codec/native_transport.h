/* The transports of the platform the program is built for, under one set of names, for programs
 * that run on both POSIX systems and Windows (the session tool): codec_native_t, codec_native_open,
 * codec_native_transport, codec_native_close and codec_native_port are the POSIX transports of
 * codec/posix_transport.h (CMake option <PKG>_POSIX) on Unix and the Win32 ones of
 * codec/win32_transport.h (<PKG>_WIN32) on Windows. The addresses are the same but for
 * the serial port's name ("/dev/ttyUSB0", "COM3"). */
#ifndef CODEC_NATIVE_TRANSPORT_H
#define CODEC_NATIVE_TRANSPORT_H

#ifdef _WIN32
#include "codec/win32_transport.h"
typedef codec_win32_t codec_native_t;
#define CODEC_NATIVE(name) codec_win32_##name
#else
#include "codec/posix_transport.h"
typedef codec_posix_t codec_native_t;
#define CODEC_NATIVE(name) codec_posix_##name
#endif

static inline codec_status_t codec_native_open(codec_native_t *t, const char *address, unsigned long baud) {
    return CODEC_NATIVE(open)(t, address, baud);
}
static inline void codec_native_transport(codec_native_t *t, codec_transport_t *out) {
    CODEC_NATIVE(transport)(t, out);
}
static inline void codec_native_close(codec_native_t *t) {
    CODEC_NATIVE(close)(t);
}
static inline void codec_native_port(codec_native_t *t, codec_port_t *out) {
    CODEC_NATIVE(port)(t, out);
}

#endif
