// Command sessions (docs/conformance.md section 8): the sans-I/O core. The caller gives the current
// time in milliseconds with every call, sends the bytes start() returns and feeds the bytes it
// receives; the session matches acks/nacks and their reply fields to the pending commands and
// reports every other packet. Everything protocol-specific is the generated session_facts.hpp.
//
// Storage is fixed: the parser's one maximum packet, a queue of at most N pending commands and at
// most kMaxHandlers registered handlers. Nothing is allocated while bytes are fed (registering a
// handler may allocate, once, inside its std::function).
//
// Bounded whatever arrives (issue 37): the session holds at most kMaxPacket bytes of undecided
// input (the parser's candidate) and the pending skip run as an offset and a count, under
// kSkipPiece bytes after every call (a run is reported in pieces of kSkipPiece bytes as it grows,
// so a caller that prints skipped bytes keeps fewer than kSkipPiece + kMaxPacket bytes plus one
// read from retain_from() on). Replies are recognised by content, not by timing: the look-ahead
// rule (feed()) drops a waiting candidate only for a complete valid packet buffered after it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <optional>
#include <type_traits>

#include "protopkg/clock.hpp"
#include "protopkg/devices.hpp"
#include "protopkg/dispatch.hpp"
#include "protopkg/packet.hpp"
#include "protopkg/parser.hpp"
#include "protopkg/session_facts.hpp"
#include "protopkg/session_types.hpp"

namespace protopkg {

inline constexpr std::int64_t kDefaultTimeoutMs = 1000;           ///< reply timeout T
inline constexpr std::int64_t kDefaultInterPacketTimeoutMs = 100; ///< inter-packet timeout P
inline constexpr std::size_t kDefaultMaxPending = 8;              ///< pending queue capacity
inline constexpr std::size_t kMaxHandlers = 16;                   ///< per-packet and per-field handlers
inline constexpr std::size_t kMaxExpected = 4;                    ///< expected reply descriptors per command
/// SKIP_PIECE of docs/conformance.md section 8: a skip run is reported as soon as its pending
/// length reaches this many bytes (a run of exactly kSkipPiece; the bytes after it start a new run).
inline constexpr std::uint64_t kSkipPiece = 65536;

/// The outcome of a command.
enum class Status : std::uint8_t { ack, nack, timeout, invalid, sent, refused };

inline const char *to_string(Status s) {
    switch (s) {
    case Status::ack:
        return "ack";
    case Status::nack:
        return "nack";
    case Status::timeout:
        return "timeout";
    case Status::invalid:
        return "invalid";
    case Status::sent:
        return "sent";
    case Status::refused:
        return "refused";
    }
    return "";
}

/// The one result of a started command. The reply packet is copied in (`packet`); the reply is
/// its field entries from payload offset reply_begin up to reply_end.
struct Result {
    Status status = Status::refused;
    const CommandRow *row = nullptr; ///< the command's layout facts
    std::uint64_t tag = 0;           ///< the tag given to start()
    bool has_code = false;           ///< ack, nack and invalid carry the ack/nack code
    std::int64_t code = 0;
    bool has_error = false; ///< invalid and refused say why
    ErrorText error{};
    std::array<std::uint8_t, kMaxExpected> expect{}; ///< expected reply descriptors
    std::uint8_t expect_count = 0;
    std::array<std::uint8_t, kMaxPacket> packet{}; ///< the reply packet (ack, nack, invalid)
    std::size_t packet_size = 0;
    std::size_t reply_begin = 0;
    std::size_t reply_end = 0;

    /// ack or sent.
    bool ok() const {
        return status == Status::ack || status == Status::sent;
    }
    const char *name() const {
        return row != nullptr ? row->name : "";
    }
    PacketView reply_packet() const {
        return PacketView{packet.data(), packet_size};
    }
    /// Calls f(const FieldEntry&) for each entry of the reply, in order.
    template <class F> void for_each_reply(F &&f) const {
        if (packet_size == 0) {
            return;
        }
        FieldIterator it(reply_packet());
        FieldEntry e;
        while (it.next(e)) {
            if (e.payload_offset >= reply_begin && e.payload_offset < reply_end) {
                f(static_cast<const FieldEntry &>(e));
            }
        }
    }
    /// The reply field of layout T (its descriptor, decoded as T), or nullopt.
    template <class T> std::optional<T> reply() const {
        std::optional<T> out;
        for_each_reply([&](const FieldEntry &e) {
            if (!out && e.kind == FieldEntry::Kind::field && e.descriptor == T::kDescriptor) {
                T value{};
                DecodeError err;
                if (decode(e.data, e.size, value, err)) {
                    out = value;
                }
            }
        });
        return out;
    }
    /// "{name}: NACK, code 3", "{name}: no reply before the timeout", "{name}: {error}", ...
    ErrorText describe() const {
        ErrorText t;
        switch (status) {
        case Status::nack:
            std::snprintf(t.text.data(), t.text.size(), "%s: NACK, code %lld", name(),
                          static_cast<long long>(code));
            break;
        case Status::timeout:
            std::snprintf(t.text.data(), t.text.size(), "%s: no reply before the timeout", name());
            break;
        case Status::invalid:
        case Status::refused:
            // Concatenated by hand: the message may be cut at the buffer's end.
            append(t, name());
            append(t, ": ");
            append(t, error.c_str());
            break;
        default:
            std::snprintf(t.text.data(), t.text.size(), "%s: %s", name(), to_string(status));
            break;
        }
        return t;
    }

  private:
    static void append(ErrorText &t, const char *text) {
        std::size_t n = std::strlen(t.text.data());
        while (*text != '\0' && n + 1 < t.text.size()) {
            t.text[n++] = *text++;
        }
        t.text[n] = '\0';
    }
};

/// One event of feed/poll/close, in stream order.
struct SessionEvent {
    /// nmea, rtcm: an NMEA sentence or RTCM3 frame between packets (its bytes in `packet`; the
    /// parser's StreamEvent kinds): a handler that does not want them ignores them.
    enum class Kind : std::uint8_t { result, packet, skip, nmea, rtcm };
    Kind kind = Kind::packet;
    const Result *result = nullptr; ///< result events (valid during the callback)
    std::uint64_t offset = 0;       ///< packet, frame or first skipped byte, counted from the first byte fed
    std::uint64_t count = 0;        ///< skipped bytes
    PacketView packet;              ///< packet and frame events (valid during the callback)
};

/// Per-call options of start().
struct StartOptions {
    std::optional<std::int64_t> timeout_ms; ///< the command's reply timeout (else the session's)
    std::optional<bool> check_device;       ///< refuse what the device does not support (else the session's)
    std::uint64_t tag = 0;                  ///< copied into the Result
};

/// What start() did: the bytes to send (`packet`, empty when nothing is to be sent; valid until
/// the next start) and, when the command completed at once (sent, refused), its result.
struct Started {
    PacketView packet;
    bool complete = false;
    Result result;
    std::int64_t deadline = 0;
};

/// What the session's rules read of `command` (a command layout): its row, function selector and
/// the parameter slots its CommandTraits give. The rules below take these facts, so they (and the
/// connection's loop) are compiled once, not once per command type.
template <class T> CommandFacts command_facts(const T &command) {
    using Traits = CommandTraits<T>;
    static_assert(Traits::kCommand, "not a command layout");
    CommandFacts f;
    f.row = &kCommandRows[Traits::kRow];
    f.function = Traits::function(command);
    for (std::size_t slot = 0; slot < kMaxParamSlots; ++slot) {
        f.params[slot] = Traits::param(command, static_cast<std::int8_t>(slot));
    }
    return f;
}

/// Why `device` does not support the command (facts of a layout of row `row`), written to `out`;
/// false when it does.
inline bool support_error(const CommandFacts &facts, std::optional<Device> device, ErrorText &out) {
    const CommandRow &row = *facts.row;
    if (!device) {
        return false;
    }
    const auto index = static_cast<std::size_t>(*device);
    const std::uint32_t bit = std::uint32_t{1} << index;
    if (!device_supports(*device, row.set, row.descriptor)) {
        std::snprintf(out.text.data(), out.text.size(), "%s is not supported by %s (%s)", row.name,
                      device_title(*device), device_manual(*device));
        return true;
    }
    if (row.device >= 0 && static_cast<std::size_t>(row.device) != index) {
        std::snprintf(out.text.data(), out.text.size(), "%s: this layout is for %s, not %s", row.name,
                      device_name(kDevices[static_cast<std::size_t>(row.device)]), device_name(*device));
        return true;
    }
    const std::optional<std::int64_t> fn = facts.function;
    if (row.has_functions && fn) {
        const bool in_layout = *fn >= 0 && *fn < 64 && ((row.functions >> *fn) & 1U) != 0;
        const std::uint32_t limited = function_devices(*fn);
        if (!in_layout || (limited != 0 && (limited & bit) == 0)) {
            const char *fname = function_name(*fn);
            if (fname != nullptr) {
                std::snprintf(out.text.data(), out.text.size(),
                              "function %s of %s is not supported by %s (%s)", fname, row.name,
                              device_title(*device), device_manual(*device));
            } else {
                std::snprintf(out.text.data(), out.text.size(),
                              "function %lld of %s is not supported by %s (%s)", static_cast<long long>(*fn),
                              row.name, device_title(*device), device_manual(*device));
            }
            return true;
        }
    }
    return false;
}

/// True when the command as given asks the device not to reply (spec `ack_suppressed_by`).
inline bool ack_suppressed(const CommandFacts &facts) {
    const CommandRow &row = *facts.row;
    if (row.ack_kind == 1) {
        const std::optional<std::int64_t> fn = facts.function;
        return fn && *fn == row.ack_value;
    }
    if (row.ack_kind == 2) {
        const std::optional<std::int64_t> v = facts.param(row.ack_param);
        return v && (row.ack_has_value ? *v == row.ack_value : *v != 0);
    }
    return false;
}

/// The extra reply time the spec gives the command as given (spec `timeout`).
inline std::int64_t allowance_ms(const CommandFacts &facts) {
    const CommandRow &row = *facts.row;
    if (!row.has_timeout) {
        return 0;
    }
    if (!row.timeout_all_functions) {
        const std::optional<std::int64_t> fn = facts.function;
        if (!fn || *fn < 0 || *fn >= 64 || ((row.timeout_functions >> *fn) & 1U) == 0) {
            return 0;
        }
    }
    std::int64_t ms = row.timeout_ms;
    if (row.timeout_param >= 0) {
        ms += facts.param(row.timeout_param).value_or(0);
    }
    return ms;
}

/// The reply field descriptors the command as given expects with its ack (spec `responses`).
inline std::uint8_t expected_replies(const CommandFacts &facts, std::array<std::uint8_t, kMaxExpected> &out) {
    const CommandRow &row = *facts.row;
    std::uint8_t n = 0;
    const std::optional<std::int64_t> fn = facts.function;
    for (std::size_t i = 0; i < row.reply_count && n < kMaxExpected; ++i) {
        const ReplyRule &r = row.replies[i];
        if (r.function >= 0 && (!fn || *fn != r.function)) {
            continue;
        }
        if (r.param >= 0) {
            const std::optional<std::int64_t> v = facts.param(r.param);
            if (!v || (r.has_value ? *v != r.value : *v == 0)) {
                continue;
            }
        }
        out[n++] = r.descriptor;
    }
    return n;
}

/// The rules of a command value (the facts its CommandTraits give).
template <class T> bool support_error(const T &command, std::optional<Device> device, ErrorText &out) {
    return support_error(command_facts(command), device, out);
}
template <class T> bool ack_suppressed(const T &command) {
    return ack_suppressed(command_facts(command));
}
template <class T> std::int64_t allowance_ms(const T &command) {
    return allowance_ms(command_facts(command));
}
template <class T>
std::uint8_t expected_replies(const T &command, std::array<std::uint8_t, kMaxExpected> &out) {
    return expected_replies(command_facts(command), out);
}

/// The device's reference time (ns) in the payload of a packet of `set` (the spec's
/// time.reference_time, kReferenceTimes): the first field the table names for `device` (every
/// device's when nullopt); nullopt when it carries none.
inline std::optional<std::int64_t> reference_ns(const std::optional<Device> &device, std::uint8_t set,
                                                const std::uint8_t *payload, std::size_t size) {
    for (const ReferenceTime &r : kReferenceTimes) {
        if ((device && r.device != *device) || (!r.shared && r.set != set)) {
            continue;
        }
        FieldIterator it(set, payload, size);
        FieldEntry e;
        while (it.next(e)) {
            if (e.kind != FieldEntry::Kind::field || e.descriptor != r.descriptor) {
                continue;
            }
            if (!r.gps) {
                if (std::size_t(r.offset) + r.size > e.size) {
                    continue;
                }
                const std::uint8_t *p = e.data + r.offset;
                std::uint64_t bits = r.size == 8   ? load_uint<8>(p)
                                     : r.size == 4 ? load_uint<4>(p)
                                     : r.size == 2 ? load_uint<2>(p)
                                                   : load_uint<1>(p);
                return static_cast<std::int64_t>(bits) * r.ns_per_unit;
            }
            if (std::size_t(r.offset) + 8 > e.size || std::size_t(r.week_offset) + r.week_size > e.size) {
                continue;
            }
            std::uint64_t bits = load_uint<8>(e.data + r.offset);
            double tow = 0;
            std::memcpy(&tow, &bits, sizeof tow);
            if (!(tow >= 0.0 && tow < 1e7)) {
                continue; // not a time of week (NaN, negative, absurd)
            }
            std::uint64_t week = r.week_size == 4 ? load_uint<4>(e.data + r.week_offset)
                                                  : load_uint<2>(e.data + r.week_offset);
            return static_cast<std::int64_t>(week) * 604800000000000LL +
                   static_cast<std::int64_t>(tow * 1e9 + 0.5);
        }
    }
    return std::nullopt;
}

/// The session core. N: the pending queue's capacity.
template <std::size_t N = kDefaultMaxPending> class Session {
    static_assert(N >= 1, "a session needs room for one pending command");

  public:
    struct Options {
        std::optional<Device> device;
        std::int64_t timeout_ms = kDefaultTimeoutMs;
        std::int64_t inter_packet_timeout_ms = kDefaultInterPacketTimeoutMs;
        bool check_device = true;
    };

    Session() = default;
    explicit Session(const Options &options) : opt_(options) {}

    const std::optional<Device> &device() const {
        return opt_.device;
    }
    const Options &options() const {
        return opt_;
    }
    std::size_t pending() const {
        return count_;
    }

    /// handler(const PacketView&, std::uint64_t offset) for every packet that is not a reply.
    /// False when kMaxHandlers handlers are registered.
    bool on_packet(std::function<void(const PacketView &, std::uint64_t)> handler) {
        if (packet_handlers_ >= kMaxHandlers) {
            return false;
        }
        packet_[packet_handlers_++] = std::move(handler);
        return true;
    }

    /// handler(const T&, const PacketView&) for every field (T::kSet, T::kDescriptor) of a packet
    /// that is not a reply and that decodes as T.
    template <class T, class F> bool on_field(F handler) {
        return on_field_data(T::kSet, T::kDescriptor,
                             [handler](const std::uint8_t *data, std::size_t size, const PacketView &p) {
                                 T value{};
                                 DecodeError err;
                                 if (decode(data, size, value, err)) {
                                     handler(static_cast<const T &>(value), p);
                                 }
                             });
    }

    /// handler(data, size, packet) for every field (set, descriptor) of a packet that is not a reply.
    bool on_field_data(std::uint8_t set, std::uint8_t descriptor,
                       std::function<void(const std::uint8_t *, std::size_t, const PacketView &)> handler) {
        if (field_handlers_ >= kMaxHandlers) {
            return false;
        }
        field_[field_handlers_++] = FieldHandler{set, descriptor, std::move(handler)};
        return true;
    }

    /// Starts a command at `now`: see Started.
    template <class T> Started start(const T &command, std::int64_t now, const StartOptions &call = {}) {
        return start(command_facts(command), command, now, call);
    }
    /// start() with the command's facts computed already (command_facts(command)).
    template <class T>
    Started start(const CommandFacts &facts, const T &command, std::int64_t now,
                  const StartOptions &call = {}) {
        static_assert(CommandTraits<T>::kCommand, "not a command layout");
        Started s;
        if (refused(facts, call, s)) {
            return s;
        }
        out_ = PacketBuilder(facts.row->set);
        started(facts, out_.add(command), now + call.timeout_ms.value_or(opt_.timeout_ms), s);
        return s;
    }
    /// start() of a command given as its field data (`size` bytes after the field header: the
    /// function selector first when the row has one) and its facts: the connection's own commands
    /// (a bare idle or ping, a recorded setting sent again), sent as they are, without a type.
    Started start_raw(const CommandFacts &facts, const std::uint8_t *data, std::size_t size, std::int64_t now,
                      const StartOptions &call = {}) {
        Started s;
        if (refused(facts, call, s)) {
            return s;
        }
        out_ = PacketBuilder(facts.row->set);
        const EncodeError e = out_.add_raw_field(facts.row->descriptor, data, size);
        started(facts, e, now + call.timeout_ms.value_or(opt_.timeout_ms), s);
        return s;
    }

    /// The earliest time at which poll() has something to do: the earliest command deadline, and
    /// for the look-ahead rule s + P + 1 while the parser waits at a candidate (since s) and the
    /// wait had not expired at the last call (once expired, a poll without bytes changes nothing:
    /// the next feed looks again by itself).
    std::optional<std::int64_t> next_deadline() const {
        std::optional<std::int64_t> t;
        for (std::size_t i = 0; i < count_; ++i) {
            if (!t || queue_[i].deadline < *t) {
                t = queue_[i].deadline;
            }
        }
        if (waiting_ && last_now_ - wait_since_ <= opt_.inter_packet_timeout_ms) {
            const std::int64_t w = wait_since_ + opt_.inter_packet_timeout_ms + 1;
            if (!t || w < *t) {
                t = w;
            }
        }
        return t;
    }

    /// Bytes received at `now`; on_event(const SessionEvent&) for each event, in order: the
    /// timeouts due at `now`; the look-ahead rule on the bytes buffered before (when the wait at the
    /// candidate began more than P ms ago); the new bytes parsed; the look-ahead rule again when the
    /// parser still waits at a candidate whose wait has expired; then the pending skip run's full
    /// pieces of kSkipPiece bytes.
    template <class Handler>
    void feed(const std::uint8_t *data, std::size_t size, std::int64_t now, Handler &&on_event) {
        feed_at(data, size, now, now * 1000000, on_event);
    }

    /// feed() with the host time the bytes were read (ns of a monotonic clock), for the clock
    /// model; feed() takes now (ms) x 1000000.
    template <class Handler>
    void feed_at(const std::uint8_t *data, std::size_t size, std::int64_t now, std::int64_t read_ns,
                 Handler &&on_event) {
        last_now_ = now;
        read_ns_ = read_ns;
        expire(now, on_event);
        auto parsed = [&](const StreamEvent &e) { route(e, on_event); };
        look_ahead(now, parsed);
        if (size > 0) {
            parser_.feed(data, size, parsed);
            track(now);
            look_ahead(now, parsed);
        }
        while (parser_.pending_skip() >= kSkipPiece) {
            parser_.report_skip_piece(kSkipPiece, parsed);
        }
    }

    /// Nothing received: the timeouts and the look-ahead rule at `now`.
    template <class Handler> void poll(std::int64_t now, Handler &&on_event) {
        feed(nullptr, 0, now, on_event);
    }

    /// End of input: poll, then the buffered bytes that are not a complete packet are skipped.
    template <class Handler> void close(std::int64_t now, Handler &&on_event) {
        poll(now, on_event);
        parser_.flush([&](const StreamEvent &e) { route(e, on_event); });
        waiting_ = false;
    }

    /// Drops the commands waiting for their replies without a result (the link to the device was
    /// lost: the caller reports them; their replies, should they come, are data).
    void forget() {
        count_ = 0;
    }
    /// The host clock model (docs/time.md): from now on every packet that is not a reply and carries
    /// the device's reference time (reference_ns) feeds *clock (owned by the caller) at the host
    /// time of its bytes (feed_at). nullptr stops it.
    void use_clock(ClockModel *clock) {
        clock_ = clock;
    }
    /// Inside a packet or field handler (or the event handler of a packet): the packet's host time
    /// by the clock model; nullopt without a model, an estimate or the reference time.
    std::optional<std::int64_t> host_ns() const {
        return packet_host_;
    }
    /// Pauses (true) or resumes the packet and field handlers (the link's own operations).
    void mute_handlers(bool muted) {
        muted_ = muted;
    }

    /// Stream offset from which a caller that prints skipped bytes must keep its input.
    std::uint64_t retain_from() const {
        return parser_.retain_from();
    }

  private:
    /// The first part of start(): the result's row, tag and expected replies; true (a refused
    /// result) when the device does not support the command. Not inlined into each start<T>
    /// (compile cost, issue 39), nor started().
    PROTOPKG_NOINLINE bool refused(const CommandFacts &f, const StartOptions &call, Started &s) const {
        s.result.row = f.row;
        s.result.tag = call.tag;
        s.result.expect_count = expected_replies(f, s.result.expect);
        const bool check = call.check_device.value_or(opt_.check_device);
        if (check && support_error(f, opt_.device, s.result.error)) {
            s.complete = true;
            s.result.status = Status::refused;
            s.result.has_error = true;
            return true;
        }
        return false;
    }
    /// The rest of start(), once the command is in out_ (`e`: how its encoding went; `at`: `now`
    /// plus the reply timeout, to which the command's allowance is added).
    PROTOPKG_NOINLINE void started(const CommandFacts &f, EncodeError e, std::int64_t at, Started &s) {
        if (e != EncodeError::none) {
            s.complete = true;
            s.result.status = Status::refused;
            s.result.has_error = true;
            std::snprintf(s.result.error.text.data(), s.result.error.text.size(), "%s",
                          to_string(out_.error()));
            return;
        }
        const PacketView bytes = out_.finish();
        s.deadline = at + allowance_ms(f);
        if (ack_suppressed(f)) {
            s.packet = bytes;
            s.complete = true;
            s.result.status = Status::sent;
            return;
        }
        if (count_ >= N) {
            s.complete = true;
            s.result.status = Status::refused;
            s.result.has_error = true;
            std::snprintf(s.result.error.text.data(), s.result.error.text.size(),
                          "%llu commands already pending", static_cast<unsigned long long>(N));
            return;
        }
        s.packet = bytes;
        Slot &slot = queue_[count_++];
        slot.row = f.row;
        slot.deadline = s.deadline;
        slot.tag = s.result.tag;
        slot.expect = s.result.expect;
        slot.expect_count = s.result.expect_count;
    }

    struct Slot {
        const CommandRow *row = nullptr;
        std::int64_t deadline = 0;
        std::uint64_t tag = 0;
        std::array<std::uint8_t, kMaxExpected> expect{};
        std::uint8_t expect_count = 0;
    };
    struct FieldHandler {
        std::uint8_t set = 0;
        std::uint8_t descriptor = 0;
        std::function<void(const std::uint8_t *, std::size_t, const PacketView &)> call;
    };

    /// The wait at the parser's candidate: it begins at `now` when the parser waits at a position it
    /// was not waiting at before.
    void track(std::int64_t now) {
        if (!parser_.buffered()) {
            waiting_ = false;
        } else if (!waiting_ || wait_at_ != parser_.buffered_at()) {
            waiting_ = true;
            wait_at_ = parser_.buffered_at();
            wait_since_ = now;
        }
    }

    /// The look-ahead rule, repeated while it finds a packet (after a jump the wait begins anew).
    template <class Parsed> void look_ahead(std::int64_t now, Parsed &parsed) {
        while (waiting_ && now - wait_since_ > opt_.inter_packet_timeout_ms && parser_.look_ahead(parsed)) {
            track(now);
        }
    }

    void remove(std::size_t i) {
        for (std::size_t j = i; j + 1 < count_; ++j) {
            queue_[j] = queue_[j + 1];
        }
        --count_;
    }

    void begin_result(const Slot &slot, Status status) {
        result_.status = status;
        result_.row = slot.row;
        result_.tag = slot.tag;
        result_.has_code = false;
        result_.code = 0;
        result_.has_error = false;
        result_.error.text[0] = '\0';
        result_.expect = slot.expect;
        result_.expect_count = slot.expect_count;
        result_.packet_size = 0;
        result_.reply_begin = 0;
        result_.reply_end = 0;
    }

    template <class Handler> void emit_result(Handler &on_event) {
        SessionEvent ev;
        ev.kind = SessionEvent::Kind::result;
        ev.result = &result_;
        on_event(static_cast<const SessionEvent &>(ev));
    }

    template <class Handler> void expire(std::int64_t now, Handler &on_event) {
        std::size_t i = 0;
        while (i < count_) {
            if (now >= queue_[i].deadline) {
                const Slot slot = queue_[i];
                remove(i);
                begin_result(slot, Status::timeout);
                emit_result(on_event);
            } else {
                ++i;
            }
        }
    }

    /// Inlined into the parser's loop (one call less per packet): the per-field handlers, rarer
    /// and bigger, stay out of line.
    template <class Handler> PROTOPKG_INLINE void route(const StreamEvent &e, Handler &on_event) {
        SessionEvent ev;
        if (e.kind == StreamEvent::Kind::skip) {
            // A run that ends (at a packet or at close) longer than a piece: its full pieces first.
            ev.kind = SessionEvent::Kind::skip;
            ev.offset = e.offset;
            std::uint64_t left = e.count;
            while (left > 0) {
                ev.count = left < kSkipPiece ? left : kSkipPiece;
                on_event(static_cast<const SessionEvent &>(ev));
                ev.offset += ev.count;
                left -= ev.count;
            }
            return;
        }
        if (e.kind != StreamEvent::Kind::packet) { // a foreign frame: handed on as it is
            ev.kind = e.kind == StreamEvent::Kind::nmea ? SessionEvent::Kind::nmea : SessionEvent::Kind::rtcm;
            ev.offset = e.offset;
            ev.packet = e.packet;
            on_event(static_cast<const SessionEvent &>(ev));
            return;
        }
        if (count_ > 0 && set_pending(e.packet.set()) && match(e.packet, on_event)) {
            return;
        }
        packet_host_.reset();
        if (clock_ != nullptr) {
            clock_packet(e.packet);
        }
        ev.kind = SessionEvent::Kind::packet;
        ev.offset = e.offset;
        ev.packet = e.packet;
        on_event(static_cast<const SessionEvent &>(ev));
        if (muted_) {
            return;
        }
        for (std::size_t i = 0; i < packet_handlers_; ++i) {
            packet_[i](e.packet, e.offset);
        }
        if (field_handlers_ > 0) {
            route_fields(e.packet);
        }
    }

    /// The clock model's step for a data packet: its host time for the handlers.
    PROTOPKG_NOINLINE void clock_packet(const PacketView &packet) {
        if (auto d = reference_ns(opt_.device, packet.set(), packet.payload(), packet.payload_size())) {
            packet_host_ = clock_->add(*d, read_ns_);
        }
    }

    PROTOPKG_NOINLINE void route_fields(const PacketView &packet) {
        FieldIterator it(packet);
        FieldEntry f;
        while (it.next(f)) {
            if (f.kind != FieldEntry::Kind::field) {
                continue;
            }
            for (std::size_t i = 0; i < field_handlers_; ++i) {
                if (field_[i].set == packet.set() && field_[i].descriptor == f.descriptor) {
                    field_[i].call(f.data, f.size, packet);
                }
            }
        }
    }

    bool set_pending(std::uint8_t set) const {
        for (std::size_t i = 0; i < count_; ++i) {
            if (queue_[i].row->set == set) {
                return true;
            }
        }
        return false;
    }

    /// Completes the pending commands this packet answers; false when it answers none.
    template <class Handler> bool match(const PacketView &packet, Handler &on_event) {
        if (!kHasAckRule) {
            return false;
        }
        bool any = false;
        FieldIterator it(packet);
        FieldEntry e;
        // The entries of the packet once, remembering where acks start (a packet has at most
        // kMaxPayload / field header fields).
        std::array<std::size_t, kMaxPayload / kFieldHeaderSize + 1> starts{};
        std::array<std::uint8_t, kMaxPayload / kFieldHeaderSize + 1> kinds{}; // 0 other, 1 ack, 2 raw ack
        std::array<std::uint8_t, kMaxPayload / kFieldHeaderSize + 1> echoes{};
        std::array<std::int64_t, kMaxPayload / kFieldHeaderSize + 1> codes{};
        std::size_t n = 0;
        while (it.next(e) && n < starts.size()) {
            starts[n] = e.payload_offset;
            kinds[n] = 0;
            if (e.kind == FieldEntry::Kind::field && e.descriptor == kAckDescriptor) {
                kinds[n] = decode_ack(packet.set(), e.data, e.size, opt_.device, echoes[n], codes[n]) ? 1 : 2;
            }
            ++n;
        }
        for (std::size_t i = 0; i < n; ++i) {
            if (kinds[i] != 1) {
                continue;
            }
            std::size_t q = count_;
            for (std::size_t j = 0; j < count_; ++j) {
                if (queue_[j].row->set == packet.set() && queue_[j].row->descriptor == echoes[i]) {
                    q = j;
                    break;
                }
            }
            if (q == count_) {
                continue;
            }
            std::size_t end = i + 1;
            while (end < n && kinds[end] == 0) {
                ++end;
            }
            const Slot slot = queue_[q];
            remove(q);
            complete(slot, packet, codes[i], i + 1 < n ? starts[i + 1] : packet.payload_size(),
                     end < n ? starts[end] : packet.payload_size());
            emit_result(on_event);
            any = true;
        }
        return any;
    }

    void complete(const Slot &slot, const PacketView &packet, std::int64_t code, std::size_t begin,
                  std::size_t end) {
        begin_result(slot, Status::ack);
        result_.has_code = true;
        result_.code = code;
        std::memcpy(result_.packet.data(), packet.data, packet.size);
        result_.packet_size = packet.size;
        result_.reply_begin = begin;
        result_.reply_end = end;
        if (code != kAckOk) {
            result_.status = Status::nack;
            return;
        }
        bool bad = false;
        bool found = slot.expect_count == 0;
        result_.for_each_reply([&](const FieldEntry &f) {
            if (bad) {
                return;
            }
            if (f.kind == FieldEntry::Kind::trailing) {
                bad = true;
                result_.error = f.text();
                return;
            }
            // Whether the reply entry decodes (with the session's device): the library's one
            // instance of the dispatch (dispatch.hpp decodes_field), not one per program.
            DecodeError check;
            if (!decodes_field(packet.set(), f.descriptor, f.data, f.size, opt_.device, check)) {
                bad = true;
                result_.error = check.text();
                return;
            }
            for (std::size_t k = 0; k < slot.expect_count; ++k) {
                if (slot.expect[k] == f.descriptor) {
                    found = true;
                }
            }
        });
        if (bad) {
            result_.status = Status::invalid;
            result_.has_error = true;
        } else if (!found) {
            result_.status = Status::invalid;
            result_.has_error = true;
            std::snprintf(result_.error.text.data(), result_.error.text.size(), "missing reply field %u",
                          static_cast<unsigned>(slot.expect[0]));
        }
    }

    Options opt_{};
    StreamParser parser_;
    bool waiting_ = false;
    std::uint64_t wait_at_ = 0;
    std::int64_t wait_since_ = 0;
    std::int64_t last_now_ = 0; ///< `now` of the last feed/poll (for next_deadline)
    std::array<Slot, N> queue_{};
    std::size_t count_ = 0;
    Result result_{};
    PacketBuilder out_{0};
    std::array<std::function<void(const PacketView &, std::uint64_t)>, kMaxHandlers> packet_{};
    std::size_t packet_handlers_ = 0;
    std::array<FieldHandler, kMaxHandlers> field_{};
    std::size_t field_handlers_ = 0;
    bool muted_ = false;
    ClockModel *clock_ = nullptr;             ///< the host clock model fed (nullptr: none)
    std::int64_t read_ns_ = 0;                ///< the host time of the bytes being fed (ns)
    std::optional<std::int64_t> packet_host_; ///< the routed packet's host time
};

} // namespace protopkg
