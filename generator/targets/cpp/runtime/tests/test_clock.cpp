// clock.hpp: the host clock model runs the corpus tests/clock/cases.txt (docs/time.md), as the C,
// Python and Rust runtimes do.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "protopkg/clock.hpp"

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
