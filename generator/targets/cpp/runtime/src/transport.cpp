// The members of Connection (transport.hpp) that decode a command by its (set, descriptor) and
// run it: each reaches the field dispatch and Connection::run of every command, so they are
// compiled once, into the library, not in every program that includes transport.hpp.
#include "protopkg/transport.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>

namespace protopkg {

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
        with_bare(link_.idle, have, [&](const auto &idle) {
            timeout = session_.options().timeout_ms + allowance_ms(idle);
            call = run_internal(idle);
        });
        if (!have) {
            return refused(call, "the idle command does not decode");
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
    with_bare(link_.ping, have, [&](const auto &ping) { call = run_internal(ping); });
    if (!have) {
        return refused(call, "the ping command does not decode");
    }
    if (call.io_error || call.result.status != Status::timeout || transport_.baud() == 0) {
        return call;
    }
    const std::vector<std::uint32_t> rates = candidate_rates();
    std::size_t i = 0;
    for (;;) {
        const std::uint32_t current = transport_.baud();
        const std::size_t next = i + 1;
        if (next >= rates.size()) {
            log("link: baud: no answer at any rate");
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
        with_bare(link_.ping, have, [&](const auto &ping) { call = run_internal(ping); });
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
        bool have = false;
        auto ignore = [](const auto &) {};
        CommandPick<decltype(ignore)> pick{ignore, have};
        decode_field(set, descriptor, read.data(), k, session_.options().device, pick);
        if (have) {
            return k - 1;
        }
    }
    return size - 1;
}

std::size_t Connection::reapply() {
    std::size_t done = 0;
    for (std::size_t i = 0; i < setting_count_; ++i) {
        const Setting s = settings_[i];
        bool have = false;
        auto resend = [&](const auto &v) {
            if (run_internal(v).ok()) {
                ++done;
            }
        };
        CommandPick<decltype(resend)> pick{resend, have};
        decode_field(s.set, s.descriptor, s.data.data(), s.size, session_.options().device, pick);
    }
    if (link_.resume.present && !idled_) {
        bool have = false;
        with_bare(link_.resume, have, [&](const auto &resume) { run_internal(resume); });
    }
    return done;
}

} // namespace protopkg
