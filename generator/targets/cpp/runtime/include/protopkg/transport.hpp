// The blocking API over a transport (docs/conformance.md section 8): Connection::run starts one
// command, writes its packet and feeds what it reads until the command's result exists, so data
// packets reach the session's handlers meanwhile. Transport is an interface; transport_posix.hpp
// has TCP and serial ones (outside the freestanding core).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>

#include "protopkg/session.hpp"

namespace protopkg {

/// A byte connection to a device.
class Transport {
  public:
    virtual ~Transport() = default;
    /// Writes all bytes; false (with `error`) when the connection failed.
    virtual bool write(const std::uint8_t *data, std::size_t size, ErrorText &error) = 0;
    /// Waits up to timeout_ms for bytes: the count read (> 0), 0 when none came, -1 (with `error`)
    /// when the connection failed or closed.
    virtual long read(std::uint8_t *buffer, std::size_t capacity, std::int64_t timeout_ms,
                      ErrorText &error) = 0;
};

/// What Connection::run returns: the command's result, or an I/O failure of the transport.
struct Call {
    Result result;
    bool io_error = false;
    ErrorText io{};
    /// The command succeeded (ack or sent) and the transport did not fail.
    bool ok() const {
        return !io_error && result.ok();
    }
    /// Why it did not succeed ("" when ok()).
    ErrorText describe() const {
        if (io_error) {
            return io;
        }
        if (result.ok()) {
            return ErrorText{};
        }
        return result.describe();
    }
};

/// The typed reply of a command of the generated API (commands.hpp): `value` holds the reply
/// field when the command expects one and succeeded.
template <class R> struct Reply {
    Call call;
    std::optional<R> value;
    bool ok() const {
        return call.ok();
    }
    explicit operator bool() const {
        return ok();
    }
};

/// A session over a transport, blocking. The session has one pending command at a time.
class Connection {
  public:
    using Clock = std::function<std::int64_t()>;

    explicit Connection(Transport &transport, const Session<1>::Options &options = {}, Clock clock = {})
        : transport_(transport), session_(options), clock_(std::move(clock)) {
        if (!clock_) {
            const auto t0 = std::chrono::steady_clock::now();
            clock_ = [t0]() {
                return static_cast<std::int64_t>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                                     std::chrono::steady_clock::now() - t0)
                                                     .count());
            };
        }
    }

    Session<1> &session() {
        return session_;
    }
    std::int64_t now_ms() const {
        return clock_();
    }
    /// Called for every event (results, packets that are not replies, skip runs), in order.
    void on_event(std::function<void(const SessionEvent &)> handler) {
        on_event_ = std::move(handler);
    }

    /// Sends the command and waits for its result (nack, timeout and refusal are results).
    template <class T> Call run(const T &command, const StartOptions &options = {}) {
        Call call;
        Started s = session_.start(command, now_ms(), options);
        if (s.packet.size > 0 && !transport_.write(s.packet.data, s.packet.size, call.io)) {
            call.io_error = true;
            call.result = s.result;
            return call;
        }
        if (s.complete) {
            call.result = s.result;
            deliver_result(call.result);
            return call;
        }
        bool done = false;
        while (!done) {
            const std::int64_t wait = session_.next_deadline().value_or(s.deadline) - now_ms();
            if (!pump(wait > 0 ? wait : 0, call, done)) {
                return call;
            }
        }
        return call;
    }

    /// Receives for duration_ms, routing every packet to the handlers; false on an I/O failure.
    bool listen(std::int64_t duration_ms, ErrorText *error = nullptr) {
        const std::int64_t end = now_ms() + duration_ms;
        Call ignored;
        bool done = false;
        for (;;) {
            const std::int64_t left = end - now_ms();
            if (left <= 0) {
                return true;
            }
            const std::int64_t next = session_.next_deadline().value_or(end) - now_ms();
            if (!pump(next > 0 && next < left ? next : left, ignored, done)) {
                if (error != nullptr) {
                    *error = ignored.io;
                }
                return false;
            }
        }
    }

    /// Ends the session: polls and flushes the parser (a trailing skip run is reported).
    void close() {
        session_.close(now_ms(), [&](const SessionEvent &e) { deliver(e); });
    }

  private:
    bool pump(std::int64_t wait_ms, Call &call, bool &done) {
        const long n = transport_.read(buf_.data(), buf_.size(), wait_ms, call.io);
        if (n < 0) {
            call.io_error = true;
            return false;
        }
        session_.feed(buf_.data(), static_cast<std::size_t>(n), now_ms(), [&](const SessionEvent &e) {
            if (e.kind == SessionEvent::Kind::result) {
                call.result = *e.result;
                done = true;
            }
            deliver(e);
        });
        return true;
    }
    void deliver(const SessionEvent &e) {
        if (on_event_) {
            on_event_(e);
        }
    }
    void deliver_result(const Result &r) {
        SessionEvent e;
        e.kind = SessionEvent::Kind::result;
        e.result = &r;
        deliver(e);
    }

    Transport &transport_;
    Session<1> session_;
    Clock clock_;
    std::function<void(const SessionEvent &)> on_event_;
    std::array<std::uint8_t, 4096> buf_{};
};

} // namespace protopkg
