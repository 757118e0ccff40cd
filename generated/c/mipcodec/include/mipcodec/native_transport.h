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
#define mipc_native_open mipc_win32_open
#define mipc_native_transport mipc_win32_transport
#define mipc_native_close mipc_win32_close
#define mipc_native_port mipc_win32_port
#else
#include "mipcodec/posix_transport.h"
typedef mipc_posix_t mipc_native_t;
#define mipc_native_open mipc_posix_open
#define mipc_native_transport mipc_posix_transport
#define mipc_native_close mipc_posix_close
#define mipc_native_port mipc_posix_port
#endif

#endif
