// POSIX transports for Connection (transport.hpp): TCP ("tcp:HOST:PORT", an IPv6 host in brackets)
// and serial ports (termios, raw 8N1, the baud rate as typed). Not part of the freestanding core:
// include it only where POSIX sockets and termios exist.
#pragma once

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>
#include <utility>

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <termios.h>
#include <unistd.h>

#include "protopkg/transport.hpp"

namespace protopkg {

/// A file descriptor transport (a connected socket or an open serial port); closes it.
class FdTransport : public Transport {
  public:
    explicit FdTransport(int fd, const char *what, std::string address = {}, long baud = 0)
        : fd_(fd), what_(what), address_(std::move(address)), baud_(baud) {}
    ~FdTransport() override {
        if (fd_ >= 0) {
            ::close(fd_);
        }
    }
    FdTransport(const FdTransport &) = delete;
    FdTransport &operator=(const FdTransport &) = delete;

    bool write(const std::uint8_t *data, std::size_t size, ErrorText &error) override {
        if (fd_ < 0) {
            reason_ = "the port is closed";
            std::snprintf(error.text.data(), error.text.size(), "%s: write failed: %s", what_,
                          reason_.c_str());
            return false;
        }
        while (size > 0) {
            const ssize_t n = send_or_write(fd_, data, size);
            if (n < 0) {
                if (errno == EINTR) {
                    continue;
                }
                reason_ = std::strerror(errno);
                std::snprintf(error.text.data(), error.text.size(), "%s: write failed: %s", what_,
                              reason_.c_str());
                return false;
            }
            data += n;
            size -= static_cast<std::size_t>(n);
        }
        return true;
    }

    long read(std::uint8_t *buffer, std::size_t capacity, std::int64_t timeout_ms,
              ErrorText &error) override {
        if (fd_ < 0) {
            reason_ = "the port is closed";
            std::snprintf(error.text.data(), error.text.size(), "%s: read failed: %s", what_,
                          reason_.c_str());
            return -1;
        }
        pollfd p{fd_, POLLIN, 0};
        const int timeout =
            timeout_ms > 2000000000 ? 2000000000 : static_cast<int>(timeout_ms < 0 ? 0 : timeout_ms);
        const int r = ::poll(&p, 1, timeout);
        if (r < 0) {
            if (errno == EINTR) {
                return 0;
            }
            reason_ = std::strerror(errno);
            std::snprintf(error.text.data(), error.text.size(), "%s: poll failed: %s", what_,
                          reason_.c_str());
            return -1;
        }
        if (r == 0) {
            return 0;
        }
        const ssize_t n = ::read(fd_, buffer, capacity);
        if (n < 0) {
            if (errno == EINTR || errno == EAGAIN) {
                return 0;
            }
            reason_ = std::strerror(errno);
            std::snprintf(error.text.data(), error.text.size(), "%s: read failed: %s", what_,
                          reason_.c_str());
            return -1;
        }
        if (n == 0) {
            reason_ = "end of file";
            std::snprintf(error.text.data(), error.text.size(), "%s: connection closed by the device", what_);
            return -1;
        }
        return static_cast<long>(n);
    }

    bool flush() override {
        if (fd_ < 0) {
            return false;
        }
        if (baud_ != 0) {
            return ::tcflush(fd_, TCIFLUSH) == 0;
        }
        // A socket: read what is there now without waiting, no more (a device that keeps
        // sending must not hold the flush: issue 37).
        int available = 0;
        if (::ioctl(fd_, FIONREAD, &available) != 0) {
            return false;
        }
        std::uint8_t buf[4096];
        while (available > 0) {
            const std::size_t want = static_cast<std::size_t>(available) < sizeof buf
                                         ? static_cast<std::size_t>(available)
                                         : sizeof buf;
            const ssize_t n = ::recv(fd_, buf, want, MSG_DONTWAIT);
            if (n <= 0) {
                return n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK);
            }
            available -= static_cast<int>(n);
        }
        return true;
    }
    std::uint32_t baud() const override {
        return static_cast<std::uint32_t>(baud_);
    }
    bool set_baud(std::uint32_t baud) override;
    bool reopen() override;
    std::string address() const override {
        return address_;
    }
    std::string reason() const override {
        return reason_;
    }
    bool sleep_ms(std::int64_t ms) override {
        timespec ts{static_cast<time_t>(ms / 1000), static_cast<long>(ms % 1000) * 1000000L};
        while (::nanosleep(&ts, &ts) != 0 && errno == EINTR) {
        }
        return true;
    }

  private:
    static ssize_t send_or_write(int fd, const std::uint8_t *data, std::size_t size) {
#ifdef MSG_NOSIGNAL
        const ssize_t n = ::send(fd, data, size, MSG_NOSIGNAL);
        if (n >= 0 || errno != ENOTSOCK) {
            return n;
        }
#endif
        return ::write(fd, data, size);
    }
    int fd_;
    const char *what_;
    std::string address_; ///< what reopen() opens
    long baud_;           ///< 0: a socket
    std::string reason_;
};

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

/// Connects to "tcp:HOST:PORT": the socket, or -1 with `error` (and `reason`: the cause alone).
inline int open_tcp_fd(const std::string &address, std::string &error, std::string &reason) {
    std::string host;
    std::string port;
    if (!parse_tcp_address(address, host, port)) {
        error = "bad TCP address '" + address + "' (expected tcp:HOST:PORT, an IPv6 host in brackets)";
        reason = error;
        return -1;
    }
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo *list = nullptr;
    const int g = ::getaddrinfo(host.c_str(), port.c_str(), &hints, &list);
    if (g != 0) {
        reason = ::gai_strerror(g);
        error = "cannot connect to " + address + ": " + reason;
        return -1;
    }
    int fd = -1;
    int last = 0;
    for (addrinfo *a = list; a != nullptr; a = a->ai_next) {
        fd = ::socket(a->ai_family, a->ai_socktype, a->ai_protocol);
        if (fd < 0) {
            last = errno;
            continue;
        }
        if (::connect(fd, a->ai_addr, a->ai_addrlen) == 0) {
            break;
        }
        last = errno;
        ::close(fd);
        fd = -1;
    }
    ::freeaddrinfo(list);
    if (fd < 0) {
        reason = std::strerror(last);
        error = "cannot connect to " + address + ": " + reason;
        return -1;
    }
    int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    return fd;
}

/// Connects to "tcp:HOST:PORT"; nullptr with `error` on failure.
inline std::unique_ptr<Transport> open_tcp(const std::string &address, std::string &error) {
    std::string reason;
    const int fd = open_tcp_fd(address, error, reason);
    if (fd < 0) {
        return nullptr;
    }
    return std::make_unique<FdTransport>(fd, "tcp", address, 0);
}

/// The termios speed of a baud rate as typed (115200), or false when the system has none.
inline bool baud_speed(long baud, speed_t &out) {
    switch (baud) {
    case 9600:
        out = B9600;
        return true;
    case 19200:
        out = B19200;
        return true;
    case 38400:
        out = B38400;
        return true;
    case 57600:
        out = B57600;
        return true;
    case 115200:
        out = B115200;
        return true;
    case 230400:
        out = B230400;
        return true;
#ifdef B460800
    case 460800:
        out = B460800;
        return true;
#endif
#ifdef B921600
    case 921600:
        out = B921600;
        return true;
#endif
#ifdef B1000000
    case 1000000:
        out = B1000000;
        return true;
#endif
#ifdef B2000000
    case 2000000:
        out = B2000000;
        return true;
#endif
#ifdef B3000000
    case 3000000:
        out = B3000000;
        return true;
#endif
    default:
        return false;
    }
}

/// Opens a serial port raw, 8N1, at `baud`: the descriptor, or -1 with `error` (and `reason`).
inline int open_serial_fd(const std::string &path, long baud, std::string &error, std::string &reason) {
    speed_t speed{};
    if (!baud_speed(baud, speed)) {
        error = "unsupported baud rate " + std::to_string(baud);
        reason = error;
        return -1;
    }
    const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        reason = std::strerror(errno);
        error = "cannot open " + path + ": " + reason;
        return -1;
    }
    termios t{};
    if (::tcgetattr(fd, &t) != 0) {
        reason = std::strerror(errno);
        error = "cannot open " + path + ": not a serial port (" + reason + ")";
        ::close(fd);
        return -1;
    }
    ::cfmakeraw(&t);
    t.c_cflag |= CLOCAL | CREAD;
    t.c_cflag &= static_cast<tcflag_t>(~(CSTOPB | PARENB));
    t.c_cc[VMIN] = 0;
    t.c_cc[VTIME] = 0;
    ::cfsetispeed(&t, speed);
    ::cfsetospeed(&t, speed);
    if (::tcsetattr(fd, TCSANOW, &t) != 0) {
        reason = std::strerror(errno);
        error = "cannot configure " + path + ": " + reason;
        ::close(fd);
        return -1;
    }
    return fd;
}

/// Opens a serial port raw, 8N1, at `baud`; nullptr with `error` on failure.
inline std::unique_ptr<Transport> open_serial(const std::string &path, long baud, std::string &error) {
    std::string reason;
    const int fd = open_serial_fd(path, baud, error, reason);
    if (fd < 0) {
        return nullptr;
    }
    return std::make_unique<FdTransport>(fd, "serial", path, baud);
}

inline bool FdTransport::set_baud(std::uint32_t baud) {
    speed_t speed{};
    termios t{};
    if (baud_ == 0 || fd_ < 0 || !baud_speed(static_cast<long>(baud), speed) || ::tcgetattr(fd_, &t) != 0 ||
        ::cfsetispeed(&t, speed) != 0 || ::cfsetospeed(&t, speed) != 0 ||
        ::tcsetattr(fd_, TCSANOW, &t) != 0) {
        return false;
    }
    baud_ = static_cast<long>(baud);
    return true;
}

inline bool FdTransport::reopen() {
    if (fd_ >= 0) {
        ::close(fd_);
        fd_ = -1;
    }
    std::string error;
    fd_ =
        baud_ == 0 ? open_tcp_fd(address_, error, reason_) : open_serial_fd(address_, baud_, error, reason_);
    return fd_ >= 0;
}

/// "tcp:HOST:PORT" or a serial port path. HOST:PORT without "tcp:" that is not an existing path
/// is refused with "did you mean tcp:HOST:PORT?".
inline std::unique_ptr<Transport> open_transport(const std::string &address, long baud, std::string &error) {
    if (address.rfind("tcp:", 0) == 0) {
        return open_tcp(address, error);
    }
    if (looks_like_tcp(address) && ::access(address.c_str(), F_OK) != 0) {
        error = "'" + address + "' is not a serial port: did you mean tcp:" + address + "?";
        return nullptr;
    }
    return open_serial(address, baud, error);
}

} // namespace protopkg
