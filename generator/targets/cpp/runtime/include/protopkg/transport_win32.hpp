// Win32 transports for Connection (transport.hpp), the Windows counterpart of transport_posix.hpp
// with the same functions (open_transport, open_tcp, open_serial, parse_tcp_address): TCP through
// Winsock 2 ("tcp:HOST:PORT", an IPv6 host in brackets) and COM serial ports ("COM3", "COM10",
// opened as "\\.\COM10"; 8N1, binary, no flow control, the baud rate as typed in the port's DCB;
// read timeouts through COMMTIMEOUTS, input flush by PurgeComm). Include it only on Windows; a
// program using it links ws2_32 (the package's CMake does so for its session tool).
#pragma once

#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <winsock2.h>
#include <ws2tcpip.h>
#include <windows.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <utility>

#include "protopkg/transport.hpp"

namespace protopkg {

namespace win32_detail {

/// The system's message for an error code (GetLastError, WSAGetLastError, a getaddrinfo result),
/// without its trailing period and line end.
inline std::string system_text(DWORD code) {
    char buf[256];
    DWORD n = ::FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, nullptr, code,
                               MAKELANGID(LANG_ENGLISH, SUBLANG_ENGLISH_US), buf, sizeof buf, nullptr);
    if (n == 0) {
        n = ::FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, nullptr, code, 0,
                             buf, sizeof buf, nullptr);
    }
    if (n == 0) {
        return "error " + std::to_string(static_cast<unsigned long>(code));
    }
    std::string text(buf, n);
    while (!text.empty() &&
           (text.back() == '\r' || text.back() == '\n' || text.back() == ' ' || text.back() == '.')) {
        text.pop_back();
    }
    return text;
}

/// The device name a serial address opens: "COMn" (any case) becomes "\\.\COMn", the name every
/// COM port answers to (COM10 and above only to it); anything else is used as given.
inline std::string serial_device_name(const std::string &address) {
    if (address.size() > 3 && (address[0] == 'C' || address[0] == 'c') &&
        (address[1] == 'O' || address[1] == 'o') && (address[2] == 'M' || address[2] == 'm') &&
        address.find_first_not_of("0123456789", 3) == std::string::npos) {
        return "\\\\.\\" + address;
    }
    return address;
}

/// 8N1 at `baud`, binary, no flow control, DTR and RTS on.
inline bool set_line(HANDLE h, std::uint32_t baud) {
    DCB dcb{};
    dcb.DCBlength = sizeof dcb;
    if (baud == 0 || !::GetCommState(h, &dcb)) {
        return false;
    }
    dcb.BaudRate = baud;
    dcb.ByteSize = 8;
    dcb.Parity = NOPARITY;
    dcb.StopBits = ONESTOPBIT;
    dcb.fBinary = TRUE;
    dcb.fParity = FALSE;
    dcb.fOutxCtsFlow = FALSE;
    dcb.fOutxDsrFlow = FALSE;
    dcb.fDtrControl = DTR_CONTROL_ENABLE;
    dcb.fDsrSensitivity = FALSE;
    dcb.fOutX = FALSE;
    dcb.fInX = FALSE;
    dcb.fErrorChar = FALSE;
    dcb.fNull = FALSE;
    dcb.fRtsControl = RTS_CONTROL_ENABLE;
    dcb.fAbortOnError = FALSE;
    return ::SetCommState(h, &dcb) != 0;
}

} // namespace win32_detail

/// Splits "tcp:HOST:PORT" ("tcp:[::1]:5000" for IPv6); false when it is not one.
inline bool parse_tcp_address(const std::string &address, std::string &host, std::string &port) {
    if (address.rfind("tcp:", 0) != 0) {
        return false;
    }
    const std::string rest = address.substr(4);
    std::size_t colon;
    if (!rest.empty() && rest[0] == '[') {
        const std::size_t close = rest.find(']');
        if (close == std::string::npos || close + 1 >= rest.size() || rest[close + 1] != ':') {
            return false;
        }
        host = rest.substr(1, close - 1);
        colon = close + 1;
    } else {
        colon = rest.rfind(':');
        if (colon == std::string::npos) {
            return false;
        }
        host = rest.substr(0, colon);
    }
    port = rest.substr(colon + 1);
    if (host.empty() || port.empty() || port.size() > 5 ||
        port.find_first_not_of("0123456789") != std::string::npos || std::atol(port.c_str()) < 1 ||
        std::atol(port.c_str()) > 65535) {
        return false;
    }
    return true;
}

/// A Winsock socket or a COM port handle; closes it.
class Win32Transport : public Transport {
  public:
    /// Opens `address` ("tcp:..." or a COM port at `baud`); check ok() (error() says why not).
    Win32Transport(std::string address, long baud) : address_(std::move(address)), baud_(baud) {
        WSADATA wsa;
        const int rc = ::WSAStartup(MAKEWORD(2, 2), &wsa);
        if (rc != 0) {
            reason_ = win32_detail::system_text(static_cast<DWORD>(rc));
            error_ = "cannot start Winsock: " + reason_;
            return;
        }
        winsock_ = true;
        open();
    }
    ~Win32Transport() override {
        close();
        if (winsock_) {
            ::WSACleanup();
        }
    }
    Win32Transport(const Win32Transport &) = delete;
    Win32Transport &operator=(const Win32Transport &) = delete;

    bool ok() const {
        return is_open();
    }
    const std::string &error() const {
        return error_;
    }

    bool write(const std::uint8_t *data, std::size_t size, ErrorText &error) override {
        if (!is_open()) {
            return fail(error, "write failed", "the port is closed");
        }
        while (size > 0) {
            const std::size_t chunk = size > 0x10000u ? 0x10000u : size;
            std::size_t done = 0;
            if (socket_ != INVALID_SOCKET) {
                const int n =
                    ::send(socket_, reinterpret_cast<const char *>(data), static_cast<int>(chunk), 0);
                if (n == SOCKET_ERROR) {
                    return fail(error, "write failed",
                                win32_detail::system_text(static_cast<DWORD>(::WSAGetLastError())));
                }
                done = static_cast<std::size_t>(n);
            } else {
                DWORD n = 0;
                if (!::WriteFile(handle_, data, static_cast<DWORD>(chunk), &n, nullptr)) {
                    return fail(error, "write failed", win32_detail::system_text(::GetLastError()));
                }
                if (n == 0) {
                    return fail(error, "write failed", "the port took no bytes");
                }
                done = n;
            }
            data += done;
            size -= done;
        }
        return true;
    }

    long read(std::uint8_t *buffer, std::size_t capacity, std::int64_t timeout_ms,
              ErrorText &error) override {
        if (!is_open()) {
            fail(error, "read failed", "the port is closed");
            return -1;
        }
        const std::int64_t wait = timeout_ms < 0 ? 0 : (timeout_ms > 0x7ffffff0 ? 0x7ffffff0 : timeout_ms);
        const int cap = capacity > 0x7fffffff ? 0x7fffffff : static_cast<int>(capacity);
        if (socket_ != INVALID_SOCKET) {
            fd_set readable;
            FD_ZERO(&readable);
            FD_SET(socket_, &readable);
            timeval tv{static_cast<long>(wait / 1000), static_cast<long>(wait % 1000) * 1000L};
            const int r = ::select(0, &readable, nullptr, nullptr, &tv);
            if (r == SOCKET_ERROR) {
                fail(error, "poll failed",
                     win32_detail::system_text(static_cast<DWORD>(::WSAGetLastError())));
                return -1;
            }
            if (r == 0) {
                return 0;
            }
            const int n = ::recv(socket_, reinterpret_cast<char *>(buffer), cap, 0);
            if (n == SOCKET_ERROR) {
                const int err = ::WSAGetLastError();
                if (err == WSAEWOULDBLOCK || err == WSAEINTR) {
                    return 0;
                }
                fail(error, "read failed", win32_detail::system_text(static_cast<DWORD>(err)));
                return -1;
            }
            if (n == 0) {
                reason_ = "end of file";
                std::snprintf(error.text.data(), error.text.size(), "%s: connection closed by the device",
                              what());
                return -1;
            }
            return n;
        }
        // A COM port: ReadFile returns as soon as a byte is there, or after `wait` ms with none
        // (MAXDWORD interval and multiplier with a constant; a zero timeout returns at once).
        if (timeout_ != wait) {
            COMMTIMEOUTS to{};
            to.ReadIntervalTimeout = MAXDWORD;
            to.ReadTotalTimeoutMultiplier = wait == 0 ? 0 : MAXDWORD;
            to.ReadTotalTimeoutConstant = static_cast<DWORD>(wait);
            if (!::SetCommTimeouts(handle_, &to)) {
                fail(error, "read failed", win32_detail::system_text(::GetLastError()));
                return -1;
            }
            timeout_ = wait;
        }
        DWORD got = 0;
        if (!::ReadFile(handle_, buffer, static_cast<DWORD>(cap), &got, nullptr)) {
            fail(error, "read failed", win32_detail::system_text(::GetLastError()));
            return -1;
        }
        return static_cast<long>(got);
    }

    bool flush() override {
        if (handle_ != INVALID_HANDLE_VALUE) {
            return ::PurgeComm(handle_, PURGE_RXCLEAR | PURGE_RXABORT) != 0;
        }
        if (socket_ == INVALID_SOCKET) {
            return false;
        }
        char buf[512];
        for (;;) { // a socket: read what is there without waiting
            fd_set readable;
            FD_ZERO(&readable);
            FD_SET(socket_, &readable);
            timeval tv{0, 0};
            if (::select(0, &readable, nullptr, nullptr, &tv) <= 0) {
                return true;
            }
            if (::recv(socket_, buf, sizeof buf, 0) <= 0) {
                return false;
            }
        }
    }
    std::uint32_t baud() const override {
        return static_cast<std::uint32_t>(baud_);
    }
    bool set_baud(std::uint32_t baud) override {
        if (baud_ == 0 || handle_ == INVALID_HANDLE_VALUE || !win32_detail::set_line(handle_, baud)) {
            return false;
        }
        baud_ = static_cast<long>(baud);
        return true;
    }
    bool reopen() override {
        close();
        return open();
    }
    std::string address() const override {
        return address_;
    }
    std::string reason() const override {
        return reason_;
    }
    bool sleep_ms(std::int64_t ms) override {
        ::Sleep(static_cast<DWORD>(ms < 0 ? 0 : ms));
        return true;
    }

  private:
    bool is_open() const {
        return socket_ != INVALID_SOCKET || handle_ != INVALID_HANDLE_VALUE;
    }
    const char *what() const {
        return baud_ == 0 ? "tcp" : "serial";
    }
    bool fail(ErrorText &error, const char *op, std::string reason) {
        reason_ = std::move(reason);
        std::snprintf(error.text.data(), error.text.size(), "%s: %s: %s", what(), op, reason_.c_str());
        return false;
    }
    void close() {
        if (socket_ != INVALID_SOCKET) {
            ::closesocket(socket_);
            socket_ = INVALID_SOCKET;
        }
        if (handle_ != INVALID_HANDLE_VALUE) {
            ::CloseHandle(handle_);
            handle_ = INVALID_HANDLE_VALUE;
        }
    }
    bool open() {
        return address_.rfind("tcp:", 0) == 0 ? open_socket() : open_port();
    }
    bool open_socket() {
        baud_ = 0;
        std::string host;
        std::string port;
        if (!parse_tcp_address(address_, host, port)) {
            error_ = "bad TCP address '" + address_ + "' (expected tcp:HOST:PORT, an IPv6 host in brackets)";
            reason_ = error_;
            return false;
        }
        addrinfo hints{};
        hints.ai_family = AF_UNSPEC;
        hints.ai_socktype = SOCK_STREAM;
        hints.ai_protocol = IPPROTO_TCP;
        addrinfo *list = nullptr;
        const int g = ::getaddrinfo(host.c_str(), port.c_str(), &hints, &list);
        if (g != 0) {
            reason_ = win32_detail::system_text(static_cast<DWORD>(g));
            error_ = "cannot connect to " + address_ + ": " + reason_;
            return false;
        }
        int last = WSAECONNREFUSED;
        for (addrinfo *a = list; a != nullptr; a = a->ai_next) {
            SOCKET s = ::socket(a->ai_family, a->ai_socktype, a->ai_protocol);
            if (s == INVALID_SOCKET) {
                last = ::WSAGetLastError();
                continue;
            }
            if (::connect(s, a->ai_addr, static_cast<int>(a->ai_addrlen)) == 0) {
                socket_ = s;
                break;
            }
            last = ::WSAGetLastError();
            ::closesocket(s);
        }
        ::freeaddrinfo(list);
        if (socket_ == INVALID_SOCKET) {
            reason_ = win32_detail::system_text(static_cast<DWORD>(last));
            error_ = "cannot connect to " + address_ + ": " + reason_;
            return false;
        }
        BOOL one = TRUE;
        ::setsockopt(socket_, IPPROTO_TCP, TCP_NODELAY, reinterpret_cast<const char *>(&one), sizeof one);
        return true;
    }
    bool open_port() {
        if (baud_ <= 0 || baud_ > 0x7fffffffL) {
            error_ = "unsupported baud rate " + std::to_string(baud_);
            reason_ = error_;
            return false;
        }
        const std::string name = win32_detail::serial_device_name(address_);
        HANDLE h = ::CreateFileA(name.c_str(), GENERIC_READ | GENERIC_WRITE, 0, nullptr, OPEN_EXISTING,
                                 FILE_ATTRIBUTE_NORMAL, nullptr);
        if (h == INVALID_HANDLE_VALUE) {
            reason_ = win32_detail::system_text(::GetLastError());
            error_ = "cannot open " + address_ + ": " + reason_;
            return false;
        }
        if (!win32_detail::set_line(h, static_cast<std::uint32_t>(baud_))) {
            reason_ = win32_detail::system_text(::GetLastError());
            error_ = "cannot configure " + address_ + ": " + reason_;
            ::CloseHandle(h);
            return false;
        }
        ::PurgeComm(h, PURGE_RXCLEAR | PURGE_TXCLEAR);
        handle_ = h;
        timeout_ = -1;
        return true;
    }

    std::string address_; ///< what reopen() opens
    long baud_;           ///< 0: a socket
    SOCKET socket_ = INVALID_SOCKET;
    HANDLE handle_ = INVALID_HANDLE_VALUE;
    std::int64_t timeout_ = -1; ///< the read timeout the port's COMMTIMEOUTS hold (-1: not set)
    bool winsock_ = false;
    std::string error_;
    std::string reason_;
};

/// Connects to "tcp:HOST:PORT"; nullptr with `error` on failure.
inline std::unique_ptr<Transport> open_tcp(const std::string &address, std::string &error) {
    auto t = std::make_unique<Win32Transport>(address, 0);
    if (!t->ok()) {
        error = t->error();
        return nullptr;
    }
    return t;
}

/// Opens a COM port ("COM3") 8N1 at `baud`; nullptr with `error` on failure.
inline std::unique_ptr<Transport> open_serial(const std::string &path, long baud, std::string &error) {
    auto t = std::make_unique<Win32Transport>(path, baud);
    if (!t->ok()) {
        error = t->error();
        return nullptr;
    }
    return t;
}

/// "tcp:HOST:PORT" or a COM port. HOST:PORT without "tcp:" is refused with "did you mean
/// tcp:HOST:PORT?".
inline std::unique_ptr<Transport> open_transport(const std::string &address, long baud, std::string &error) {
    if (address.rfind("tcp:", 0) == 0) {
        return open_tcp(address, error);
    }
    if (looks_like_tcp(address)) {
        error = "'" + address + "' is not a serial port: did you mean tcp:" + address + "?";
        return nullptr;
    }
    return open_serial(address, baud, error);
}

} // namespace protopkg
