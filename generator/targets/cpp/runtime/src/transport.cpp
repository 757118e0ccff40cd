// The members of Connection (transport.hpp) compiled once, into the library: the part of run() that
// does not depend on the command's type (write, wait for the result, wrong-model check, record),
// and the connection's own commands (idle, ping, resume, identity, the recorded settings), which it
// holds as bytes and sends as they are (Session::start_raw) with their facts decoded through one
// visitor (facts_of): one field dispatch here, not one per site, and no run() per command type.
#include "protopkg/transport.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>

namespace protopkg {

namespace {

/// The facts of a decoded command layout (the other layouts are not commands).
struct FactsPick {
    CommandFacts &facts;
    bool have = false;
    template <class T> void field(const T &v) {
        if constexpr (CommandTraits<T>::kCommand) {
            have = true;
            facts = command_facts(v);
        }
    }
    void raw(const DecodeError &) {}
};

} // namespace

bool Connection::facts_of(std::uint8_t set, std::uint8_t descriptor, const std::uint8_t *data,
                          std::size_t size, CommandFacts &facts) {
    FactsPick pick{facts};
    decode_field(set, descriptor, data, size, session_.options().device, pick);
    return pick.have;
}

Call Connection::run_raw(const CommandFacts &facts, const std::uint8_t *data, std::size_t size,
                         const StartOptions &options) {
    return run_started(facts, session_.start_raw(facts, data, size, now_ms(), options));
}

Call Connection::run_started(const CommandFacts &facts, const Started &s) {
    Call call;
    std::array<std::uint8_t, kMaxPacket> sent{};
    const std::size_t sent_size = s.packet.size <= sent.size() ? s.packet.size : 0;
    if (sent_size > 0) {
        std::memcpy(sent.data(), s.packet.data, sent_size);
    }
    if (s.packet.size > 0 && !transport_.write(s.packet.data, s.packet.size, call.io)) {
        call.result = s.result;
        return lost_call(call);
    }
    if (s.complete) {
        call.result = s.result;
        deliver_result(call.result);
    } else {
        bool done = false;
        while (!done) {
            const std::int64_t wait = session_.next_deadline().value_or(s.deadline) - now_ms();
            if (!pump(wait > 0 ? wait : 0, call, done)) {
                return lost_call(call);
            }
        }
    }
    if (!internal_ && !identified_ && call.result.status == Status::nack && call.result.has_code &&
        unknown_command_code(call.result.code)) {
        identified_ = true;
        call.note = model_mismatch();
    }
    if (!internal_ && call.result.ok()) {
        record(facts, sent.data(), sent_size);
    }
    return call;
}

Call Connection::run_internal(const CommandFacts &facts, const std::uint8_t *data, std::size_t size,
                              const StartOptions &options) {
    const bool was = internal_;
    internal_ = true;
    session_.mute_handlers(true);
    Call call = run_raw(facts, data, size, options);
    session_.mute_handlers(was);
    internal_ = was;
    return call;
}

Call Connection::run_bare(const LinkCommand &c, bool &have, const StartOptions &options) {
    CommandFacts facts;
    have = facts_of(c.set, c.descriptor, nullptr, 0, facts);
    if (!have) {
        return Call{};
    }
    return run_internal(facts, nullptr, 0, options);
}

std::string Connection::model_mismatch() {
    const std::optional<Device> told = session_.options().device;
    if (!told || !kIdentity.present) {
        return {};
    }
    StartOptions unchecked;
    unchecked.check_device = false;
    bool have = false;
    const Call call = run_bare(LinkCommand{true, kIdentity.set, kIdentity.command}, have, unchecked);
    std::string note;
    if (!have || call.io_error || call.result.status != Status::ack) {
        return note;
    }
    bool seen = false;
    call.result.for_each_reply([&](const FieldEntry &e) {
        if (!seen && e.kind == FieldEntry::Kind::field && e.descriptor == kIdentity.reply &&
            e.size >= kIdentity.model_offset + kIdentity.model_length) {
            seen = true;
            note = model_note(*told, e.data + kIdentity.model_offset, kIdentity.model_length);
        }
    });
    return note;
}

void Connection::record(const CommandFacts &facts, const std::uint8_t *packet, std::size_t size) {
    const CommandRow &row = *facts.row;
    const std::optional<std::int64_t> fn = facts.function;
    if (link_.idle.present && row.set == link_.idle.set && row.descriptor == link_.idle.descriptor) {
        idled_ = true;
    }
    if (link_.resume.present && row.set == link_.resume.set && row.descriptor == link_.resume.descriptor) {
        idled_ = false;
    }
    if (!fn || (*fn != 1 && *fn != 6)) {
        return;
    }
    const PacketView view{packet, size};
    FieldIterator it(view);
    FieldEntry e;
    if (!it.next(e) || e.kind != FieldEntry::Kind::field || e.size == 0) {
        return;
    }
    const std::size_t key = key_size(row.set, row.descriptor, e.data, e.size);
    std::size_t i = 0;
    while (i < setting_count_ && !(settings_[i].set == row.set && settings_[i].descriptor == row.descriptor &&
                                   settings_[i].key_size == key &&
                                   std::memcmp(settings_[i].data.data() + 1, e.data + 1, key) == 0)) {
        ++i;
    }
    if (i == setting_count_ && setting_count_ == kMaxSettings) {
        i = 0;
    }
    if (i < setting_count_) {
        for (std::size_t j = i; j + 1 < setting_count_; ++j) {
            settings_[j] = settings_[j + 1];
        }
        --setting_count_;
    }
    Setting &slot = settings_[setting_count_++];
    slot.set = row.set;
    slot.descriptor = row.descriptor;
    slot.key_size = key;
    slot.size = e.size;
    std::memcpy(slot.data.data(), e.data, e.size);
}

Call Connection::to_idle() {
    Call call;
    if (!link_.idle.present) {
        log("link: idle: the protocol has no idle command");
        return refused(call, "the protocol has no idle command");
    }
    bool have = false;
    std::int64_t timeout = session_.options().timeout_ms;
    for (unsigned attempt = 1; attempt <= kLinkIdleAttempts; ++attempt) {
        dropped_ = 0;
        CommandFacts idle;
        have = facts_of(link_.idle.set, link_.idle.descriptor, nullptr, 0, idle);
        if (have) {
            timeout = session_.options().timeout_ms + allowance_ms(idle);
            call = run_internal(idle, nullptr, 0);
        }
        if (!have) {
            return refused(call, "the idle command does not decode");
        }
        if (call.io_error && !internal_) {
            // the application's idle command went with the port: lost, and reconnected as for its
            // other commands (not retried)
            return lost_call(call);
        }
        if (!call.io_error && call.result.status == Status::ack) {
            log("link: idle: ACK on attempt " + std::to_string(attempt) + " of " +
                std::to_string(kLinkIdleAttempts) + " (" + std::to_string(dropped_) + " bytes dropped)");
            if (!internal_) {
                idled_ = true;
            }
            return call;
        }
        if (call.io_error || call.result.status != Status::timeout) {
            return call;
        }
        if (attempt == kLinkIdleAttempts) {
            break;
        }
        std::string line = "link: idle: no ACK in " + std::to_string(timeout) + " ms";
        if (dropped_ > 0) {
            line += " while streaming (" + std::to_string(dropped_) + " bytes dropped)";
        }
        log(line + ", flushing, attempt " + std::to_string(attempt + 1) + " of " +
            std::to_string(kLinkIdleAttempts));
        flush_input();
        if (!drain(link_.quiet_ms)) {
            call.io_error = true;
            set_text(call.io, "link lost while getting to idle");
            return call;
        }
        flush_input();
    }
    log("link: idle: no ACK after " + std::to_string(kLinkIdleAttempts) + " attempts, giving up");
    return call;
}

Call Connection::find_baud() {
    Call call;
    if (!link_.ping.present) {
        return refused(call, "the protocol has no ping command");
    }
    bool have = false;
    call = run_bare(link_.ping, have);
    if (!have) {
        return refused(call, "the ping command does not decode");
    }
    if (call.io_error || call.result.status != Status::timeout || transport_.baud() == 0) {
        return call;
    }
    const std::vector<std::uint32_t> rates = candidate_rates();
    const std::uint32_t configured = transport_.baud();
    std::size_t i = 0;
    for (;;) {
        const std::uint32_t current = transport_.baud();
        const std::size_t next = i + 1;
        if (next >= rates.size()) {
            log("link: baud: no answer at any rate");
            if (transport_.baud() != configured) {
                (void)transport_.set_baud(configured); // back at the configured rate
            }
            call.io_error = false;
            call.result.status = Status::timeout;
            return call;
        }
        log("link: baud: no answer at " + std::to_string(current) + ", trying " +
            std::to_string(rates[next]));
        i = next;
        if (!transport_.set_baud(rates[i])) {
            continue;
        }
        flush_input();
        call = run_bare(link_.ping, have);
        if (call.io_error) {
            return call;
        }
        if (call.result.status == Status::ack) {
            log("link: baud: device answers at " + std::to_string(rates[i]));
            return call;
        }
    }
}

std::size_t Connection::key_size(std::uint8_t set, std::uint8_t descriptor, const std::uint8_t *data,
                                 std::size_t size) {
    std::array<std::uint8_t, kMaxPacket> read{};
    std::memcpy(read.data(), data, size);
    read[0] = 2;
    for (std::size_t k = 1; k <= size; ++k) {
        CommandFacts facts;
        if (facts_of(set, descriptor, read.data(), k, facts)) {
            return k - 1;
        }
    }
    return size - 1;
}

std::size_t Connection::reapply() {
    std::size_t done = 0;
    for (std::size_t i = 0; i < setting_count_; ++i) {
        const Setting s = settings_[i];
        CommandFacts facts;
        if (facts_of(s.set, s.descriptor, s.data.data(), s.size, facts) &&
            run_internal(facts, s.data.data(), s.size).ok()) {
            ++done;
        }
    }
    if (link_.resume.present && !idled_) {
        bool have = false;
        run_bare(link_.resume, have);
    }
    return done;
}

} // namespace protopkg
