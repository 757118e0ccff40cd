// clock.h: the host clock model runs the corpus tests/clock/cases.txt (docs/time.md), as the C++,
// Python and Rust runtimes do.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

extern "C" {
#include "codec/clock.h"
#include "codec/framing.h"
#include "codec/session.h"
}

namespace {

struct ClockCase {
    std::string name;
    std::vector<std::pair<int64_t, int64_t>> packets;
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
        codec_clock_t model;
        codec_clock_init(&model);
        for (const auto &p : c.packets) {
            int64_t host = 0;
            bool estimated =
                codec_clock_add(&model, p.first, p.second, &host); // (argument order is unspecified)
            EXPECT_EQ(estimated, model.estimated);
        }
        ASSERT_FALSE(c.expects.empty());
        for (const auto &e : c.expects) {
            if (e[0] == "estimated") {
                EXPECT_EQ(model.estimated, e[1] == "1");
                int64_t host = 0;
                EXPECT_EQ(codec_clock_host_time(&model, c.packets.back().first, &host), model.estimated);
            } else if (e[0] == "restarts") {
                EXPECT_EQ(model.restarts, std::strtoul(e[1].c_str(), nullptr, 10));
            } else if (e[0] == "drift_ppm") {
                EXPECT_LE(std::fabs(codec_clock_drift_ppm(&model) - std::strtod(e[1].c_str(), nullptr)),
                          std::strtod(e[2].c_str(), nullptr));
            } else if (e[0] == "host_ns") {
                int64_t host = 0;
                ASSERT_TRUE(codec_clock_host_time(&model, std::strtoll(e[1].c_str(), nullptr, 10), &host));
                EXPECT_LE(std::llabs(host - std::strtoll(e[2].c_str(), nullptr, 10)),
                          std::strtoll(e[3].c_str(), nullptr, 10));
                int64_t last = 0;
                ASSERT_TRUE(codec_clock_host_time(&model, c.packets.back().first, &last));
                EXPECT_EQ(codec_clock_offset_ns(&model), last - c.packets.back().first);
            } else if (e[0] == "bound_max_ns") {
                EXPECT_GE(model.bound_ns, 0);
                EXPECT_LE(model.bound_ns, std::strtoll(e[1].c_str(), nullptr, 10));
            } else {
                ADD_FAILURE() << "unknown expectation " << e[0];
            }
        }
    }
}

TEST(Clock, RestartsWhenDeviceTimeGoesBack) {
    codec_clock_t model;
    codec_clock_init(&model);
    for (int64_t k = 0; k < 300; k++) {
        codec_clock_add(&model, 1000000000 + k * 10000000, 5000000000000 + k * 10000000, nullptr);
    }
    EXPECT_TRUE(model.estimated);
    EXPECT_EQ(model.restarts, 0u);
    EXPECT_FALSE(codec_clock_add(&model, 1000000, 5000000000000 + 301 * 10000000LL, nullptr));
    EXPECT_EQ(model.restarts, 1u);
}

namespace {

struct HostLog {
    codec_session_t *session;
    std::vector<std::pair<bool, int64_t>> hosts;
};

void on_packet(void *ctx, const codec_event_t *) {
    HostLog *log = static_cast<HostLog *>(ctx);
    int64_t host = 0;
    bool ok = codec_session_host_ns(log->session, &host);
    log->hosts.emplace_back(ok, host);
}

// A data packet of the test protocol's sensor set carrying alpha's reference time (shared 0xD5, ns).
std::vector<uint8_t> stamped(uint64_t ns) {
    uint8_t data[8], buf[CODEC_MAX_PACKET];
    size_t n = 0;
    for (int i = 0; i < 8; i++) {
        data[CODEC_LITTLE_ENDIAN ? i : 7 - i] = static_cast<uint8_t>(ns >> (8 * i));
    }
    codec_packet_builder_t b;
    codec_packet_begin(&b, buf, sizeof buf, 0x80);
    codec_packet_add_field(&b, 0xD5, data, sizeof data);
    EXPECT_EQ(codec_packet_finish(&b, &n), CODEC_OK);
    return std::vector<uint8_t>(buf, buf + n);
}

} // namespace

// The session feeds the model the reference time of every data packet at the host time of its
// bytes (codec_session_feed_at) and gives the packet handler the packet's host time.
TEST(Clock, SessionFeedsTheModel) {
    for (codec_device_t device : {CODEC_DEVICE_ALPHA, CODEC_DEVICE_BETA}) {
        codec_session_config_t c;
        codec_session_config_init(&c);
        c.device = device;
        codec_session_t s;
        ASSERT_EQ(codec_session_init(&s, &c), CODEC_OK);
        codec_clock_t model;
        codec_clock_init(&model);
        codec_session_use_clock(&s, &model);
        HostLog log{&s, {}};
        codec_session_on_packet(&s, on_packet, &log);
        const int64_t host0 = 9000000000000;
        int64_t a = 0;
        for (int64_t k = 0; k < 500; k++) { // 10 s at 50 Hz, the device's clock 100 ppm fast, no delay
            int64_t d = 3000000000 + k * 20000000;
            a = host0 +
                static_cast<int64_t>(std::llround(static_cast<double>(d - 3000000000) / (1 + 100e-6)));
            std::vector<uint8_t> p = stamped(static_cast<uint64_t>(d));
            codec_session_feed_at(&s, p.data(), p.size(), static_cast<uint64_t>(a / 1000000), a);
        }
        ASSERT_EQ(log.hosts.size(), 500u);
        if (device == CODEC_DEVICE_BETA) { // beta has no reference time in the spec: nothing fed
            EXPECT_FALSE(model.estimated);
            EXPECT_FALSE(log.hosts.back().first);
            continue;
        }
        EXPECT_FALSE(log.hosts.front().first); // nothing before two buckets closed
        ASSERT_TRUE(model.estimated);
        // No delay or jitter: the fit is the true line, to the whole-ns rounding of arrival times.
        EXPECT_LT(std::fabs(codec_clock_drift_ppm(&model) - 100.0), 0.01);
        ASSERT_TRUE(log.hosts.back().first);
        EXPECT_LE(std::llabs(log.hosts.back().second - a), 1);
    }
}
