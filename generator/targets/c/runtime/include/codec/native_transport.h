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
#define codec_native_open codec_win32_open
#define codec_native_transport codec_win32_transport
#define codec_native_close codec_win32_close
#define codec_native_port codec_win32_port
#else
#include "codec/posix_transport.h"
typedef codec_posix_t codec_native_t;
#define codec_native_open codec_posix_open
#define codec_native_transport codec_posix_transport
#define codec_native_close codec_posix_close
#define codec_native_port codec_posix_port
#endif

#endif
