// The session corpus (tests/sessions/, docs/conformance.md section 8) through the session core,
// as the runner rule says: before each step, poll at every wake-up the session reports up to the
// step's time; start each command (a refused or sent result is reported at once) or feed the
// bytes; at the end, poll while commands are pending, then close. Each receive is also fed split
// at every position (two feeds at the same time): the lines must not change. The table is
// generated per package (session_cases.hpp).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "session_cases.hpp"
#include "test_support.hpp"

namespace {

struct Runner {
    codec_session_t session;
    codec_device_t device = CODEC_DEVICE_ANY;
    std::vector<uint8_t> received;
    std::string out;

    void line(const std::string &text) {
        out += text;
        out += '\n';
    }
};

std::string text_of(size_t (*fmt)(char *, size_t, const void *), const void *arg) {
    std::string s(1024, '\0');
    size_t n = fmt(&s[0], s.size(), arg);
    if (n >= s.size()) {
        s.assign(n + 1, '\0');
        fmt(&s[0], s.size(), arg);
    }
    s.resize(n);
    return s;
}

struct ResultArg {
    const codec_result_t *r;
    codec_device_t device;
};

size_t result_fmt(char *buf, size_t cap, const void *arg) {
    const ResultArg *a = static_cast<const ResultArg *>(arg);
    return codec_json_result_line(a->r, a->r->tag, a->device, buf, cap);
}

struct PacketArg {
    const codec_event_t *ev;
    codec_device_t device;
    const std::vector<uint8_t> *received;
};

size_t packet_fmt(char *buf, size_t cap, const void *arg) {
    const PacketArg *a = static_cast<const PacketArg *>(arg);
    if (a->ev->kind == CODEC_EVENT_SKIP) {
        return codec_json_skip_line(a->ev->offset, a->received->data() + a->ev->offset, (size_t)a->ev->length,
                                    buf, cap);
    }
    return codec_json_packet_line(a->ev->packet, (size_t)a->ev->length, a->ev->offset, a->device, buf, cap);
}

void on_event(void *ctx, const codec_session_event_t *ev) {
    Runner *r = static_cast<Runner *>(ctx);
    if (ev->kind == CODEC_SESSION_RESULT) {
        ResultArg a{ev->result, r->device};
        r->line(text_of(result_fmt, &a));
    } else {
        PacketArg a{ev->stream, r->device, &r->received};
        r->line(text_of(packet_fmt, &a));
    }
}

// The lines the core reports for a case; split = (receive step index, position) feeds that step
// in two parts at the same time.
std::string run_case(const session_cases::Case &c, size_t split_step = SIZE_MAX, size_t split_at = 0) {
    using test_support::from_hex;
    using test_support::to_hex;
    Runner r;
    codec_session_config_t config;
    codec_session_config_init(&config);
    config.device = c.device;
    config.timeout_ms = c.timeout_ms;
    config.inter_packet_timeout_ms = c.inter_packet_timeout_ms;
    config.on_event = on_event;
    config.ctx = &r;
    r.device = c.device;
    EXPECT_EQ(codec_session_init(&r.session, &config), CODEC_OK);
    for (const auto &step : c.steps) {
        if (step.receive) {
            std::vector<uint8_t> data = from_hex(step.receive);
            r.received.insert(r.received.end(), data.begin(), data.end());
        }
    }
    size_t fed = 0;
    uint64_t now = 0;
    uintptr_t number = 0;
    for (size_t k = 0; k < c.steps.size(); ++k) {
        const auto &step = c.steps[k];
        now = step.at;
        uint64_t d;
        while (codec_session_next_deadline(&r.session, &d) && d <= now) {
            codec_session_poll(&r.session, d);
        }
        if (step.send) {
            codec_field_value_t command;
            char msg[CODEC_ERROR_MESSAGE_MAX + 200];
            number++;
            std::string text(step.send);
            EXPECT_EQ(codec_json_command_line(text.data(), text.size(), &command, msg, sizeof msg), CODEC_OK)
                << msg;
            codec_start_options_t opt;
            codec_start_options_init(&opt);
            opt.tag = number;
            uint8_t packet[CODEC_MAX_PACKET];
            codec_started_t started;
            EXPECT_EQ(codec_session_start(&r.session, &command, now, &opt, packet, sizeof packet, &started),
                      CODEC_OK);
            if (step.bytes && !started.done) {
                EXPECT_EQ(to_hex(std::vector<uint8_t>(packet, packet + started.packet_len)), step.bytes)
                    << "command " << number;
            }
            if (started.done) {
                ResultArg a{&started.result, r.device};
                r.line(text_of(result_fmt, &a));
            }
            continue;
        }
        std::vector<uint8_t> data = from_hex(step.receive);
        if (k == split_step) {
            codec_session_feed(&r.session, data.data(), split_at, now);
            codec_session_feed(&r.session, data.data() + split_at, data.size() - split_at, now);
        } else {
            codec_session_feed(&r.session, data.data(), data.size(), now);
        }
        fed += data.size();
    }
    while (codec_session_pending(&r.session) > 0) {
        uint64_t d = now;
        codec_session_next_deadline(&r.session, &d);
        now = d > now ? d : now;
        codec_session_poll(&r.session, now);
    }
    codec_session_close(&r.session, now);
    return r.out;
}

TEST(SessionCorpus, EveryCaseWholeAndSplitEverywhere) {
    const auto &all = session_cases::cases();
    for (const auto &c : all) {
        EXPECT_EQ(run_case(c), c.expect) << c.name;
        for (size_t k = 0; k < c.steps.size(); ++k) {
            if (!c.steps[k].receive) {
                continue;
            }
            size_t n = std::string(c.steps[k].receive).size() / 2;
            for (size_t cut = 1; cut < n; ++cut) {
                std::string got = run_case(c, k, cut);
                if (got != c.expect) {
                    EXPECT_EQ(got, c.expect) << c.name << ": receive step " << k << " split at " << cut;
                    break;
                }
            }
        }
    }
}

} // namespace
