// protopkg-session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N] [--auto-baud]
// [--reconnect-ms N]: the session conformance tool (docs/conformance.md section 8). Reads command
// packets as canonical JSON lines on stdin (or {"link": "idle"}: get the device to idle), runs them
// in order over the connection and prints one result line per command; every other packet received
// (and every skip run) is printed as its canonical line, in arrival order. The steps of getting
// through (a baud rate searched, a lost port reopened) are "link: ..." lines on stderr.
// Exit 0 when every line ran, 1 when a line was bad (reported on stderr with its number and
// skipped), 2 for usage or connection errors.
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "protopkg/session_json.hpp"
#ifdef _WIN32
#include "protopkg/transport_win32.hpp"
#else
#include "protopkg/transport_posix.hpp"
#endif

namespace {

const char *const kProg = "protopkg-session";
const char *const kUsage =
    "usage: session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N] [--auto-baud] "
    "[--reconnect-ms N]";

int usage_error(const std::string &message) {
    std::fprintf(stderr, "%s: %s (%s)\n", kProg, message.c_str(), kUsage);
    return 2;
}

bool int_option(const std::string &text, long low, long &out) {
    if (text.empty() || text.size() > 12 || text.find_first_not_of("0123456789") != std::string::npos) {
        return false;
    }
    out = std::atol(text.c_str());
    return out >= low;
}

/// {"link":"idle"}: 1; {"link":"listen","ms":M} (either key first, any white space): 2 with ms; else 0.
int link_line(const std::string &line, long &ms) {
    std::string c;
    for (const char ch : line) {
        if (ch != ' ' && ch != '\t' && ch != '\r' && ch != '\f' && ch != '\v') {
            c += ch;
        }
    }
    if (c == "{\"link\":\"idle\"}") {
        return 1;
    }
    std::string digits;
    const std::string a = "{\"link\":\"listen\",\"ms\":";
    const std::string b = ",\"link\":\"listen\"}";
    if (c.rfind(a, 0) == 0 && c.size() > a.size() + 1 && c.back() == '}') {
        digits = c.substr(a.size(), c.size() - a.size() - 1);
    } else if (c.rfind("{\"ms\":", 0) == 0 && c.size() > 6 + b.size() &&
               c.compare(c.size() - b.size(), b.size(), b) == 0) {
        digits = c.substr(6, c.size() - 6 - b.size());
    } else {
        return 0;
    }
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) {
        return 0;
    }
    ms = std::atol(digits.c_str());
    return 2;
}

void print(const std::string &text) {
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}

/// The result line of a command lost with the port.
std::string lost_line(unsigned long number, const std::string &error) {
    std::string line =
        "{\"line\":" + std::to_string(number) + ",\"result\":\"lost\",\"code\":null,\"reply\":[],\"error\":";
    protopkg::JsonWriter w(protopkg::string_sink, &line);
    w.string(error.c_str(), error.size());
    return line + "}";
}

bool blank(const std::string &line) {
    return line.find_first_not_of(" \t\r\n") == std::string::npos;
}

/// Valid UTF-8 (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
bool utf8(const std::string &s) {
    std::size_t i = 0;
    while (i < s.size()) {
        const auto c = static_cast<unsigned char>(s[i]);
        std::size_t n = 0;
        unsigned char lo = 0x80;
        unsigned char hi = 0xBF;
        if (c < 0x80) {
            ++i;
            continue;
        }
        if (c >= 0xC2 && c <= 0xDF) {
            n = 1;
        } else if (c >= 0xE0 && c <= 0xEF) {
            n = 2;
            lo = c == 0xE0 ? 0xA0 : 0x80;
            hi = c == 0xED ? 0x9F : 0xBF;
        } else if (c >= 0xF0 && c <= 0xF4) {
            n = 3;
            lo = c == 0xF0 ? 0x90 : 0x80;
            hi = c == 0xF4 ? 0x8F : 0xBF;
        } else {
            return false;
        }
        if (i + n >= s.size()) {
            return false;
        }
        for (std::size_t k = 1; k <= n; ++k) {
            const auto b = static_cast<unsigned char>(s[i + k]);
            if (k == 1 ? (b < lo || b > hi) : (b >> 6) != 2) {
                return false;
            }
        }
        i += n + 1;
    }
    return true;
}

} // namespace

int main(int argc, char **argv) {
    std::string connect;
    long timeout_ms = protopkg::kDefaultTimeoutMs;
    long baud = 115200;
    long reconnect_ms = 0;
    bool auto_baud = false;
    std::optional<protopkg::Device> device_id;
    std::vector<std::string> args(argv + 1, argv + argc);
    for (const std::string &a : args) {
        if (a == "-h" || a == "--help") {
            std::printf("%s\n", kUsage);
            return 0;
        }
    }
    for (std::size_t i = 0; i < args.size();) {
        const std::string a = args[i];
        const std::size_t eq = a.find('=');
        const std::string name = a.substr(0, eq);
        std::string value;
        if (a == "--auto-baud") {
            auto_baud = true;
            ++i;
            continue;
        }
        if (name != "--connect" && name != "--timeout-ms" && name != "--device" && name != "--baud" &&
            name != "--reconnect-ms") {
            return usage_error("unknown argument '" + a + "'");
        }
        if (eq == std::string::npos) {
            if (i + 1 >= args.size()) {
                return usage_error(name + " needs a value");
            }
            value = args[i + 1];
            ++i;
        } else {
            value = a.substr(eq + 1);
        }
        ++i;
        if (name == "--connect") {
            connect = value;
        } else if (name == "--timeout-ms") {
            if (!int_option(value, 0, timeout_ms)) {
                return usage_error(name + " needs an integer >= 0, not '" + value + "'");
            }
        } else if (name == "--baud") {
            if (!int_option(value, 1, baud)) {
                return usage_error(name + " needs an integer >= 1, not '" + value + "'");
            }
        } else if (name == "--reconnect-ms") {
            if (!int_option(value, 0, reconnect_ms)) {
                return usage_error(name + " needs an integer >= 0, not '" + value + "'");
            }
        } else {
            device_id = protopkg::device_from_name(value.c_str());
            if (!device_id) {
                std::string all;
                for (protopkg::Device d : protopkg::kDevices) {
                    all += std::string(all.empty() ? "" : ", ") + protopkg::device_name(d);
                }
                return usage_error("unknown device '" + value + "' (one of: " + all + ")");
            }
        }
    }
    if (connect.empty()) {
        return usage_error("--connect ADDRESS is required");
    }
#ifdef SIGPIPE
    std::signal(SIGPIPE, SIG_IGN);
#endif
    std::string error;
    std::unique_ptr<protopkg::Transport> transport = protopkg::open_transport(connect, baud, error);
    if (!transport) {
        std::fprintf(stderr, "%s: %s\n", kProg, error.c_str());
        return 2;
    }
    protopkg::Session<1>::Options options;
    options.device = device_id;
    options.timeout_ms = timeout_ms;
    // The received bytes not yet decided on, to print skip runs (from stream offset hist_base).
    std::vector<std::uint8_t> hist;
    std::uint64_t hist_base = 0;
    // Keep every byte read until the parser has decided on it (done by wrapping the transport).
    struct Recording : protopkg::Transport {
        protopkg::Transport &inner;
        std::vector<std::uint8_t> &hist;
        std::uint64_t &base;
        protopkg::Connection *device = nullptr;
        Recording(protopkg::Transport &t, std::vector<std::uint8_t> &h, std::uint64_t &b)
            : inner(t), hist(h), base(b) {}
        bool write(const std::uint8_t *data, std::size_t size, protopkg::ErrorText &err) override {
            return inner.write(data, size, err);
        }
        long read(std::uint8_t *buffer, std::size_t capacity, std::int64_t timeout_ms,
                  protopkg::ErrorText &err) override {
            const std::uint64_t keep = device->session().retain_from();
            if (keep > base) {
                hist.erase(hist.begin(), hist.begin() + static_cast<std::ptrdiff_t>(keep - base));
                base = keep;
            }
            const long n = inner.read(buffer, capacity, timeout_ms, err);
            if (n > 0) {
                hist.insert(hist.end(), buffer, buffer + n);
            }
            return n;
        }
        bool flush() override {
            return inner.flush();
        }
        std::uint32_t baud() const override {
            return inner.baud();
        }
        bool set_baud(std::uint32_t rate) override {
            return inner.set_baud(rate);
        }
        bool reopen() override {
            return inner.reopen();
        }
        std::string address() const override {
            return inner.address();
        }
        std::string reason() const override {
            return inner.reason();
        }
        bool sleep_ms(std::int64_t ms) override {
            return inner.sleep_ms(ms);
        }
    };
    Recording recording(*transport, hist, hist_base);
    protopkg::Connection dev(recording, options);
    recording.device = &dev;
    dev.on_event([&](const protopkg::SessionEvent &e) {
        const std::string line = protopkg::session_event_line(
            e, device_id, [&](std::uint64_t offset) { return hist.data() + (offset - hist_base); });
        std::fwrite(line.data(), 1, line.size(), stdout);
        std::fputc('\n', stdout);
        std::fflush(stdout);
    });
    protopkg::LinkOptions link;
    link.log = [](const std::string &text) {
        std::fprintf(stderr, "%s\n", text.c_str());
        std::fflush(stderr);
    };
    link.reconnect_ms = reconnect_ms;
    dev.link_options(link);
    if (auto_baud && recording.baud() != 0) {
        const protopkg::Call found = dev.find_baud();
        if (!found.ok()) {
            std::fprintf(stderr, "%s: %s\n", kProg,
                         found.io_error ? found.io.c_str() : "no answer at any baud rate");
            return 2;
        }
    }
    int status = 0;
    unsigned long number = 0;
    std::string line;
    while (std::getline(std::cin, line)) {
        ++number;
        if (!utf8(line)) {
            std::fprintf(stderr, "%s: line %lu: not UTF-8\n", kProg, number);
            status = 1;
            continue;
        }
        if (blank(line)) {
            continue;
        }
        long listen_ms = 0;
        const int link_kind = link_line(line, listen_ms);
        if (link_kind == 1) {
            const protopkg::Call idle = dev.to_idle();
            if (idle.io_error || idle.result.status == protopkg::Status::refused) {
                std::fprintf(stderr, "%s: line %lu: %s\n", kProg, number,
                             idle.io_error ? idle.io.c_str() : idle.result.error.c_str());
                return 2;
            }
            protopkg::Result r = idle.result;
            r.tag = number;
            protopkg::SessionEvent e;
            e.kind = protopkg::SessionEvent::Kind::result;
            e.result = &r;
            print(protopkg::session_event_line(
                e, device_id, [&](std::uint64_t offset) { return hist.data() + (offset - hist_base); }));
            continue;
        }
        if (link_kind == 2) {
            protopkg::ErrorText err;
            if (!dev.listen(listen_ms, &err)) {
                std::fprintf(stderr, "%s: %s\n", kProg, err.c_str());
                return 2;
            }
            print("{\"line\":" + std::to_string(number) + ",\"listened\":" + std::to_string(listen_ms) + "}");
            continue;
        }
        protopkg::Call call;
        bool ran = false;
        const bool ok = protopkg::with_command_from_line(line, error, [&](const auto &command) {
            protopkg::StartOptions start;
            start.tag = number;
            call = dev.run(command, start);
            ran = true;
        });
        if (!ok && !ran) {
            std::fprintf(stderr, "%s: line %lu: %s\n", kProg, number, error.c_str());
            status = 1;
            continue;
        }
        if (call.io_error) {
            if (call.lost && dev.connected()) { // reconnected: the command was lost with the port
                print(lost_line(number, call.io.str()));
                continue;
            }
            std::fprintf(stderr, "%s: %s\n", kProg, call.io.c_str());
            return 2;
        }
    }
    dev.close();
    return status;
}
