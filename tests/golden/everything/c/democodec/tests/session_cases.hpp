// The session corpus (tests/sessions/demo/, docs/conformance.md section 8) as a table for
// tests/session_test.cpp. Generated: do not edit.
#pragma once

#include <vector>

#include "democodec/democodec.h"

namespace session_cases {

struct Step {
    unsigned at;
    const char *send;    // a command line, or nullptr
    const char *bytes;   // the packet the command must send (hex), or nullptr
    const char *receive; // the bytes received (hex), or nullptr
};

struct Case {
    const char *name;
    democ_device_t device;
    unsigned timeout_ms;
    unsigned inter_packet_timeout_ms;
    std::vector<Step> steps;
    const char *expect; // the lines, each ending with a newline
};

inline const std::vector<Case> &cases() {
    static const std::vector<Case> all = {};
    return all;
}

} // namespace session_cases
