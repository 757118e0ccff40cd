// The runner rule of docs/conformance.md section 8 for the session corpus (tests/sessions/),
// used by the generated tests/test_sessions.cpp.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "protopkg/session_json.hpp"
#include "test_support.hpp"

namespace protopkg_test {

/// One timed step: `send` a command line (with the packet it must build, or nullptr), or `receive` bytes.
struct SessionStep {
    std::int64_t at;
    const char *send;
    const char *bytes;
    const char *receive;
};

/// The lines the session core reports for a case; split = (receive step index, position) feeds
/// that step in two parts at the same time.
inline std::vector<std::string> run_session_case(const char *device, std::int64_t timeout_ms,
                                                 std::int64_t inter_packet_timeout_ms,
                                                 const std::vector<SessionStep> &steps,
                                                 std::size_t split_step = ~std::size_t{0},
                                                 std::size_t split_at = 0) {
    protopkg::Session<>::Options options;
    if (device != nullptr) {
        options.device = protopkg::device_from_name(device);
    }
    options.timeout_ms = timeout_ms;
    options.inter_packet_timeout_ms = inter_packet_timeout_ms;
    protopkg::Session<> s(options);
    std::vector<std::string> out;
    std::vector<std::uint8_t> stream; // every byte fed, for the skip lines
    auto emit = [&](const protopkg::SessionEvent &e) {
        out.push_back(protopkg::session_event_line(
            e, options.device, [&](std::uint64_t offset) { return stream.data() + offset; }));
    };
    auto advance = [&](std::int64_t t) {
        for (;;) {
            const std::optional<std::int64_t> d = s.next_deadline();
            if (!d || *d > t) {
                return;
            }
            s.poll(*d, emit);
        }
    };
    std::uint64_t number = 0;
    std::int64_t now = 0;
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const SessionStep &step = steps[k];
        now = step.at;
        advance(now);
        if (step.send != nullptr) {
            ++number;
            std::string error;
            const bool ok = protopkg::with_command_from_line(step.send, error, [&](const auto &command) {
                protopkg::StartOptions call;
                call.tag = number;
                protopkg::Started st = s.start(command, now, call);
                if (step.bytes != nullptr && !st.complete) {
                    EXPECT_EQ(
                        to_hex(std::vector<std::uint8_t>(st.packet.data, st.packet.data + st.packet.size)),
                        step.bytes)
                        << "command " << number;
                }
                if (st.complete) {
                    protopkg::SessionEvent e;
                    e.kind = protopkg::SessionEvent::Kind::result;
                    e.result = &st.result;
                    emit(e);
                }
            });
            EXPECT_TRUE(ok) << step.send << "\n" << error;
            continue;
        }
        const std::vector<std::uint8_t> data = from_hex(step.receive);
        stream.insert(stream.end(), data.begin(), data.end());
        if (k == split_step) {
            s.feed(data.data(), split_at, now, emit);
            s.feed(data.data() + split_at, data.size() - split_at, now, emit);
        } else {
            s.feed(data.data(), data.size(), now, emit);
        }
    }
    while (s.pending() > 0) {
        const std::int64_t d = s.next_deadline().value_or(now);
        now = d > now ? d : now;
        s.poll(now, emit);
    }
    s.close(now, emit);
    return out;
}

/// A case of the corpus: whole, then each receive split at every position (the first split that
/// differs is reported).
inline void check_session_case(const char *device, std::int64_t timeout_ms,
                               std::int64_t inter_packet_timeout_ms, const std::vector<SessionStep> &steps,
                               const std::vector<std::string> &expect) {
    EXPECT_EQ(run_session_case(device, timeout_ms, inter_packet_timeout_ms, steps), expect) << "whole";
    for (std::size_t k = 0; k < steps.size(); ++k) {
        if (steps[k].receive == nullptr) {
            continue;
        }
        const std::size_t n = from_hex(steps[k].receive).size();
        for (std::size_t at = 0; at <= n; ++at) {
            const std::vector<std::string> got =
                run_session_case(device, timeout_ms, inter_packet_timeout_ms, steps, k, at);
            if (got != expect) {
                EXPECT_EQ(got, expect) << "receive step " << k << " split at " << at;
                return;
            }
        }
    }
}

} // namespace protopkg_test
