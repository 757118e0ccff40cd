// clock.hpp: the host clock model runs the corpus tests/clock/cases.txt (docs/time.md), as the C,
// Python and Rust runtimes do.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "protopkg/clock.hpp"
#include "protopkg/packet.hpp"
#include "protopkg/session.hpp"

namespace {

struct ClockCase {
    std::string name;
    std::vector<std::pair<std::int64_t, std::int64_t>> packets;
    std::vector<std::vector<std::string>> expects;
};

std::vector<ClockCase> read_cases() {
    std::ifstream in(CLOCK_CASES);
    EXPECT_TRUE(in.good()) << CLOCK_CASES;
    std::vector<ClockCase> cases;
    ClockCase c;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string what;
        if (!(words >> what) || what[0] == '#') {
            continue;
        }
        if (what == "case") {
            c = ClockCase();
            words >> c.name;
        } else if (what == "p") {
            long long d = 0, a = 0;
            words >> d >> a;
            c.packets.emplace_back(d, a);
        } else if (what == "expect") {
            std::vector<std::string> e;
            std::string w;
            while (words >> w) {
                e.push_back(w);
            }
            c.expects.push_back(e);
        } else if (what == "end") {
            cases.push_back(c);
        } else {
            ADD_FAILURE() << "unknown line " << line;
        }
    }
    return cases;
}

} // namespace

TEST(Clock, Corpus) {
    std::vector<ClockCase> cases = read_cases();
    ASSERT_EQ(cases.size(), 7u);
    for (const ClockCase &c : cases) {
        SCOPED_TRACE(c.name);
        protopkg::ClockModel model;
        for (const auto &p : c.packets) {
            bool host = model.add(p.first, p.second)
                            .has_value(); // (before estimated(): argument order is unspecified)
            EXPECT_EQ(host, model.estimated());
        }
        ASSERT_FALSE(c.expects.empty());
        for (const auto &e : c.expects) {
            if (e[0] == "estimated") {
                EXPECT_EQ(model.estimated(), e[1] == "1");
                EXPECT_EQ(model.drift_ppm().has_value(), model.estimated());
                EXPECT_EQ(model.offset_ns().has_value(), model.estimated());
            } else if (e[0] == "restarts") {
                EXPECT_EQ(model.restarts(), std::strtoul(e[1].c_str(), nullptr, 10));
            } else if (e[0] == "drift_ppm") {
                ASSERT_TRUE(model.drift_ppm());
                EXPECT_LE(std::fabs(*model.drift_ppm() - std::strtod(e[1].c_str(), nullptr)),
                          std::strtod(e[2].c_str(), nullptr));
            } else if (e[0] == "host_ns") {
                auto host = model.host_time(std::strtoll(e[1].c_str(), nullptr, 10));
                ASSERT_TRUE(host);
                EXPECT_LE(std::llabs(*host - std::strtoll(e[2].c_str(), nullptr, 10)),
                          std::strtoll(e[3].c_str(), nullptr, 10));
                EXPECT_EQ(*model.offset_ns(),
                          *model.host_time(c.packets.back().first) - c.packets.back().first);
            } else if (e[0] == "bound_max_ns") {
                EXPECT_GE(model.bound_ns(), 0);
                EXPECT_LE(model.bound_ns(), std::strtoll(e[1].c_str(), nullptr, 10));
            } else {
                ADD_FAILURE() << "unknown expectation " << e[0];
            }
        }
    }
}

TEST(Clock, RestartsWhenDeviceTimeGoesBack) {
    protopkg::ClockModel model;
    for (std::int64_t k = 0; k < 300; k++) {
        model.add(1000000000 + k * 10000000, 5000000000000 + k * 10000000);
    }
    EXPECT_TRUE(model.estimated());
    EXPECT_EQ(model.restarts(), 0u);
    EXPECT_FALSE(model.add(1000000, 5000000000000 + 301 * 10000000LL));
    EXPECT_EQ(model.restarts(), 1u);
}

namespace {

// A data packet of the test protocol's sensor set (0x80) carrying alpha's reference time (shared
// 0xD5, ns, in the protocol's byte order).
std::vector<std::uint8_t> stamped(std::uint64_t ns) {
    std::uint8_t data[8];
    for (int i = 0; i < 8; i++) {
        data[protopkg::kBigEndian ? 7 - i : i] = static_cast<std::uint8_t>(ns >> (8 * i));
    }
    protopkg::PacketBuilder b(0x80);
    EXPECT_EQ(b.add_raw_field(0xD5, data, sizeof data), protopkg::EncodeError::none);
    const protopkg::PacketView p = b.finish();
    return std::vector<std::uint8_t>(p.data, p.data + p.size);
}

} // namespace

// The session feeds the model the reference time of every data packet at the host time of its
// bytes (feed_at) and gives the packet handler the packet's host time (host_ns).
TEST(Clock, SessionFeedsTheModel) {
    for (protopkg::Device device : {protopkg::Device::alpha, protopkg::Device::beta}) {
        protopkg::Session<>::Options o;
        o.device = device;
        protopkg::Session<> s(o);
        protopkg::ClockModel model;
        s.use_clock(&model);
        std::vector<std::optional<std::int64_t>> hosts;
        s.on_packet([&](const protopkg::PacketView &, std::uint64_t) { hosts.push_back(s.host_ns()); });
        const std::int64_t host0 = 9000000000000;
        std::int64_t a = 0;
        for (std::int64_t k = 0; k < 500; k++) { // 10 s at 50 Hz, the device's clock 100 ppm fast, no delay
            const std::int64_t d = 3000000000 + k * 20000000;
            a = host0 + std::llround(static_cast<double>(d - 3000000000) / (1 + 100e-6));
            const std::vector<std::uint8_t> p = stamped(static_cast<std::uint64_t>(d));
            s.feed_at(p.data(), p.size(), a / 1000000, a, [](const protopkg::SessionEvent &) {});
        }
        ASSERT_EQ(hosts.size(), 500u);
        if (device == protopkg::Device::beta) { // beta has no reference time in the spec: nothing fed
            EXPECT_FALSE(model.drift_ppm().has_value());
            EXPECT_FALSE(hosts.back().has_value());
            continue;
        }
        EXPECT_FALSE(hosts.front().has_value()); // nothing before two buckets closed
        ASSERT_TRUE(model.drift_ppm().has_value());
        // No delay or jitter: the fit is the true line, to the whole-ns rounding of arrival times.
        EXPECT_LT(std::fabs(*model.drift_ppm() - 100.0), 0.01);
        ASSERT_TRUE(hosts.back().has_value());
        EXPECT_LE(std::llabs(*hosts.back() - a), 1);
        // A packet without the reference time has no host time; feed() takes now (ms) x 1000000.
        const std::uint8_t other[] = {1, 2};
        protopkg::PacketBuilder b(0x80);
        b.add_raw_field(0x04, other, sizeof other);
        const protopkg::PacketView p = b.finish();
        s.feed(p.data, p.size, a / 1000000 + 20, [](const protopkg::SessionEvent &) {});
        ASSERT_EQ(hosts.size(), 501u);
        EXPECT_FALSE(hosts.back().has_value());
    }
}
