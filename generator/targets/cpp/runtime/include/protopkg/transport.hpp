// The blocking API over a transport (docs/conformance.md section 8): Connection::run starts one
// command, writes its packet and feeds what it reads until the command's result exists, so data
// packets reach the session's handlers meanwhile. Transport is an interface; transport_posix.hpp
// has TCP and serial ones (outside the freestanding core).
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <vector>
#include <algorithm>

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

    // Getting through (docs/conformance.md section 8): what a port can do beyond reading and
    // writing. The defaults: none of it.
    /// Discards the input received and not yet read; false when it cannot.
    virtual bool flush() {
        return false;
    }
    /// The baud rate the port is open at; 0: it has none (TCP).
    virtual std::uint32_t baud() const {
        return 0;
    }
    /// Changes the host side's baud rate; false when it cannot.
    virtual bool set_baud(std::uint32_t) {
        return false;
    }
    /// Closes and opens the same address again; false when it is not back (yet).
    virtual bool reopen() {
        return false;
    }
    /// The address, for the log ("/tmp/x/dev").
    virtual std::string address() const {
        return {};
    }
    /// Why the port failed last ("Input/output error"), for the log.
    virtual std::string reason() const {
        return {};
    }
    /// Sleeps ms milliseconds; false when it cannot (the connection then waits by reading).
    virtual bool sleep_ms(std::int64_t) {
        return false;
    }
};

/// How a Connection gets through (Connection::link_options).
struct LinkOptions {
    /// Receives each step as one line ("link: baud: device answers at 921600"); may be empty.
    std::function<void(const std::string &)> log;
    std::int64_t reconnect_ms = 10000;     ///< reopen a lost port for up to this long (0: never)
    std::int64_t reopen_interval_ms = 500; ///< between reopen attempts
    std::int64_t quiet_ms = 50;            ///< the input drained after a flush, before a retry
    LinkCommand idle = kLinkIdle;          ///< the spec's commands (link section)
    LinkCommand ping = kLinkPing;
    LinkCommand resume = kLinkResume;
};

/// What Connection::run returns: the command's result, or an I/O failure of the transport.
struct Call {
    Result result;
    bool io_error = false;
    bool lost = false; ///< the port was lost under the command and the connection reopened it (io: "link
                       ///< lost: REASON")
    ErrorText io{};
    /// What the result alone does not tell: after the first NACK for a command the device does not
    /// know, a connection told a device asks it what it is (the spec's identity command, once)
    /// and, when it is another model (model_note), says so here ("connected device is 3DM-GX5-45,
    /// this session was told cv7_ins"); else empty.
    std::string note;
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

/// The wrong-model rule (the same in every language): `name` (size bytes, as the device reported
/// it) with spaces and NULs at either end removed, is not empty and, upper case without spaces and
/// punctuation (a byte outside ASCII kept), is none of device_model_names(told): then "connected
/// device is NAME, this session was told ID", NAME with every byte outside printable ASCII written
/// \xNN; else empty (the name is the device's, or the device does not say).
inline std::string model_note(Device told, const std::uint8_t *name, std::size_t size) {
    std::size_t a = 0;
    std::size_t b = size;
    while (a < b && (name[a] == ' ' || name[a] == 0)) {
        ++a;
    }
    while (b > a && (name[b - 1] == ' ' || name[b - 1] == 0)) {
        --b;
    }
    if (a == b) {
        return {};
    }
    std::string plain;
    for (std::size_t i = a; i < b; ++i) {
        const std::uint8_t c = name[i];
        if ((c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z') || c >= 0x80) {
            plain.push_back(static_cast<char>(c));
        } else if (c >= 'a' && c <= 'z') {
            plain.push_back(static_cast<char>(c - ('a' - 'A')));
        }
    }
    for (const char *const *n = device_model_names(told); !plain.empty() && *n != nullptr; ++n) {
        if (plain == *n) {
            return {};
        }
    }
    static const char kHex[] = "0123456789abcdef";
    std::string out = "connected device is ";
    for (std::size_t i = a; i < b; ++i) {
        const std::uint8_t c = name[i];
        if (c >= 0x20 && c <= 0x7E) {
            out.push_back(static_cast<char>(c));
        } else {
            out += "\\x";
            out.push_back(kHex[c >> 4]);
            out.push_back(kHex[c & 0x0F]);
        }
    }
    return out + ", this session was told " + device_name(told);
}

/// A session over a transport, blocking. The session has one pending command at a time.
class Connection {
  public:
    using Clock = std::function<std::int64_t()>;

    explicit Connection(Transport &transport, const Session<1>::Options &options = {}, Clock clock = {})
        : transport_(transport), session_(options), clock_(std::move(clock)), identified_(!options.device) {
        if (!clock_) {
            const auto t0 = std::chrono::steady_clock::now();
            clock_ns_ = [t0]() {
                return static_cast<std::int64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                                     std::chrono::steady_clock::now() - t0)
                                                     .count());
            };
            clock_ = [ns = clock_ns_]() { return ns() / 1000000; };
        } else {
            clock_ns_ = [ms = clock_]() { return ms() * 1000000; };
        }
    }

    Session<1> &session() {
        return session_;
    }
    std::int64_t now_ms() const {
        return clock_();
    }
    /// The host time (ns of the monotonic clock; the injected clock's ms x 1000000) at which the
    /// bytes fed to the session were read: the clock model's arrival times (session().use_clock).
    std::int64_t now_ns() const {
        return clock_ns_();
    }
    /// Called for every event (results, packets that are not replies, skip runs), in order.
    void on_event(std::function<void(const SessionEvent &)> handler) {
        on_event_ = std::move(handler);
    }

    /// Sends the command and waits for its result (nack, timeout and refusal are results).
    /// A transport failure ends the command with an I/O error "link lost: REASON" (it is not sent
    /// again); with link options that allow it, the port is reopened first (reconnect()).
    /// Only what the type knows is compiled per command type (its facts and its encoding, in
    /// Session::start); the write, the wait for the result, the wrong-model check and the record are
    /// one function of the library (src/transport.cpp).
    template <class T> Call run(const T &command, const StartOptions &options = {}) {
        const CommandFacts facts = command_facts(command);
        return run_started(facts, session_.start(facts, command, now_ms(), options));
    }

    /// Gives the connection its getting-through options (the transport's port operations are
    /// used as it has them). Without it, a connection does not reconnect.
    void link_options(const LinkOptions &options) {
        link_ = options;
    }
    /// False after a lost port that was not reopened.
    bool connected() const {
        return connected_;
    }

    /// Gets the device to idle (the protocol's idle command), also while it streams at full rate:
    /// the packets that arrive meanwhile are counted and dropped; on no ACK the input is flushed
    /// (transport and parser), drained for the quiet time and the command sent again,
    /// kLinkIdleAttempts times in all, each with the command's timeout.
    Call to_idle();

    /// Pings the device; on a port with a baud rate and no answer, tries the device's supported
    /// rates (the configured one, the default, then from the highest down), each after the settle
    /// time and a flush, and stays at the first that answers.
    Call find_baud();

    /// Reopens a lost port every reopen_interval_ms until reconnect_ms have passed, then gets to
    /// idle and re-sends the recorded configuration commands in order. run() and listen() call it
    /// when the transport fails. True when reconnected.
    bool reconnect() {
        if (link_.reconnect_ms <= 0) {
            connected_ = false;
            return false;
        }
        const std::string reason = transport_.reason();
        const std::string address = transport_.address();
        log("link: port lost (" + (reason.empty() ? std::string("unknown error") : reason) + "), reopening " +
            (address.empty() ? std::string("the port") : address) + " every " +
            std::to_string(link_.reopen_interval_ms) + " ms");
        session_.forget();
        const bool was = internal_;
        internal_ = true;
        session_.close(now_ms(), [&](const SessionEvent &e) { deliver(e); });
        const std::int64_t start = now_ms();
        while (!transport_.reopen()) {
            if (now_ms() - start + link_.reopen_interval_ms > link_.reconnect_ms) {
                internal_ = was;
                connected_ = false;
                log("link: gave up reopening " + (address.empty() ? std::string("the port") : address) +
                    " after " + std::to_string(link_.reconnect_ms) + " ms");
                return false;
            }
            sleep(link_.reopen_interval_ms);
        }
        connected_ = true;
        std::size_t applied = 0;
        const Call idle = to_idle();
        if (idle.ok()) {
            reapply();
            applied = setting_count_;
        }
        internal_ = was;
        log("link: reconnected after " + seconds(now_ms() - start) + " s, re-applied " +
            std::to_string(applied) + " settings");
        return true;
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
                if (!internal_ && reconnect()) {
                    ignored = Call{};
                    continue;
                }
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

    /// The settings recorded for a reconnect (the latest per key; one more forgets the oldest).
    static constexpr std::size_t kMaxSettings = 64;
    std::size_t settings() const {
        return setting_count_;
    }

  private:
    struct Setting {
        std::uint8_t set = 0;
        std::uint8_t descriptor = 0;
        std::size_t key_size = 0; ///< key: the data bytes after the function selector its read sends
        std::size_t size = 0;
        std::array<std::uint8_t, kMaxPacket> data{}; ///< the field data
    };

    static LinkOptions no_reconnect() {
        LinkOptions o;
        o.reconnect_ms = 0;
        return o;
    }
    void log(const std::string &line) {
        if (link_.log) {
            link_.log(line);
        }
    }
    static void set_text(ErrorText &out, const std::string &text) {
        std::snprintf(out.text.data(), out.text.size(), "%s", text.c_str());
    }
    /// Milliseconds as seconds with one decimal ("1.4"), rounded to the nearest tenth.
    static std::string seconds(std::int64_t ms) {
        const std::int64_t tenths = (ms + 50) / 100;
        return std::to_string(tenths / 10) + "." + std::to_string(tenths % 10);
    }
    Call &refused(Call &call, const char *why) {
        call.result.status = Status::refused;
        call.result.has_error = true;
        set_text(call.result.error, why);
        return call;
    }
    Call &lost_call(Call &call) {
        call.io_error = true;
        const std::string reason = transport_.reason();
        const std::string io = call.io.str();
        if (!internal_ && link_.reconnect_ms > 0) {
            call.lost = true;
            reconnect();
            set_text(call.io, "link lost: " + (reason.empty() ? io : reason));
        } else if (!internal_) {
            connected_ = false;
        }
        return call;
    }

    /// The facts of the command (set, descriptor) whose field data is `data` (`size` bytes) as the
    /// session's device decodes it; false when it does not decode as a command layout. The
    /// library's one dispatch of the connection (src/transport.cpp).
    bool facts_of(std::uint8_t set, std::uint8_t descriptor, const std::uint8_t *data, std::size_t size,
                  CommandFacts &facts);
    /// Sends the command given as field data (Session::start_raw) and waits for its result.
    Call run_raw(const CommandFacts &facts, const std::uint8_t *data, std::size_t size,
                 const StartOptions &options = {});
    /// The rest of run() once the command is started: write, wait, wrong-model check, record.
    Call run_started(const CommandFacts &facts, const Started &s);

    /// Asks the device for its identity (the spec's identity command, sent whatever the device):
    /// model_note of the model name it reports.
    std::string model_mismatch();

    /// The command of link option `c` (no parameters) run as the connection's own (run_internal);
    /// `have`: false when (set, descriptor) with no data is not a command layout.
    Call run_bare(const LinkCommand &c, bool &have, const StartOptions &options = {});
    /// run_raw as the connection's own command: events counted and dropped, handlers paused, not recorded.
    Call run_internal(const CommandFacts &facts, const std::uint8_t *data, std::size_t size,
                      const StartOptions &options = {});

    bool drain(std::int64_t ms) {
        const bool was = internal_;
        internal_ = true;
        session_.mute_handlers(true);
        const bool ok = listen(ms);
        session_.mute_handlers(was);
        internal_ = was;
        return ok;
    }
    void sleep(std::int64_t ms) {
        if (ms > 0 && !transport_.sleep_ms(ms)) {
            drain(ms);
        }
    }
    /// Flushes the input: the transport's, then the parser's buffered bytes (skipped).
    void flush_input() {
        transport_.flush();
        const bool was = internal_;
        internal_ = true;
        session_.close(now_ms(), [&](const SessionEvent &e) { deliver(e); });
        internal_ = was;
    }

    /// The rates to try, most likely first: the configured one, the default, then the supported
    /// rates from the highest down (with no device selected, every device's), each once.
    std::vector<std::uint32_t> candidate_rates() const {
        std::vector<std::uint32_t> out;
        std::vector<std::uint32_t> all;
        auto add = [](std::vector<std::uint32_t> &v, std::uint32_t r) {
            if (r != 0 && std::find(v.begin(), v.end(), r) == v.end()) {
                v.push_back(r);
            }
        };
        add(out, transport_.baud());
        const std::optional<Device> device = session_.options().device;
        for (const Device d : kDevices) {
            if (!device) {
                add(out, device_default_baud(d));
            }
        }
        for (const Device d : kDevices) {
            if (device && *device != d) {
                continue;
            }
            if (device) {
                add(out, device_default_baud(d));
            }
            for (const std::uint32_t r : device_baud_rates(d)) {
                add(all, r);
            }
        }
        std::sort(all.begin(), all.end(), [](std::uint32_t a, std::uint32_t b) { return a > b; });
        for (const std::uint32_t r : all) {
            add(out, r);
        }
        return out;
    }

    /// How many data bytes after the function selector a setting's read sends: the shortest prefix
    /// of the written data that decodes as that command's read (function 2); without one, all.
    std::size_t key_size(std::uint8_t set, std::uint8_t descriptor, const std::uint8_t *data,
                         std::size_t size);

    /// Records a setting the application wrote (function write or write_no_ack of a command with a
    /// function selector, acknowledged or sent): the latest per key replaces the earlier one and
    /// moves to the end; one more than kMaxSettings keys forgets the oldest. Also notes whether the
    /// last idle or resume command was an idle.
    void record(const CommandFacts &facts, const std::uint8_t *packet, std::size_t size);

    /// Re-sends the recorded configuration in order; how many were acknowledged (or sent).
    std::size_t reapply();

    bool pump(std::int64_t wait_ms, Call &call, bool &done) {
        const long n = transport_.read(buf_.data(), buf_.size(), wait_ms, call.io);
        if (n < 0) {
            call.io_error = true;
            return false;
        }
        const std::int64_t read_ns = now_ns();
        if (internal_) {
            dropped_ += static_cast<std::uint64_t>(n); // data, garbage and the reply alike
        }
        session_.feed_at(buf_.data(), static_cast<std::size_t>(n), read_ns / 1000000, read_ns,
                         [&](const SessionEvent &e) {
                             if (e.kind == SessionEvent::Kind::result) {
                                 call.result = *e.result;
                                 done = true;
                             }
                             deliver(e);
                         });
        return true;
    }
    void deliver(const SessionEvent &e) {
        if (internal_) { // the connection's own operation: dropped (its bytes counted in pump)
            return;
        }
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
    Clock clock_ns_; ///< the same clock in ns
    std::function<void(const SessionEvent &)> on_event_;
    std::array<std::uint8_t, 4096> buf_{};
    LinkOptions link_ = no_reconnect();
    bool internal_ = false;
    bool connected_ = true;
    bool idled_ = false; // the application's last idle or resume command was an idle
    std::uint64_t dropped_ = 0;
    bool identified_ = false; // the wrong-model check is done (or not to do: no device)
    std::array<Setting, kMaxSettings> settings_{};
    std::size_t setting_count_ = 0;
};

/// True for HOST:PORT without "tcp:" (127.0.0.1:5000, localhost:5000, [::1]:5000): a numeric
/// port, no '/' or '\\' (a path such as /dev/ttyUSB0 or \\.\COM10), an IPv6 host in brackets. The four
/// languages share the rule; transport_posix.hpp and transport_win32.hpp refuse such an address with
/// "did you mean tcp:HOST:PORT?" (POSIX: unless a file of that name exists).
inline bool looks_like_tcp(const std::string &address) {
    const std::size_t colon = address.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == address.size() ||
        address.find_first_not_of("0123456789", colon + 1) != std::string::npos ||
        address.find_first_of("/\\") != std::string::npos) {
        return false;
    }
    if (address.find(':') == colon) {
        return true;
    }
    return address[0] == '[' && address[colon - 1] == ']';
}

} // namespace protopkg
