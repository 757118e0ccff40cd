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

#include "codec/clock.h"

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
            EXPECT_EQ(codec_clock_add(&model, p.first, p.second, &host), model.estimated);
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
