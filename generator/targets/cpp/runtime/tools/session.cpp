// protopkg-session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N] [--auto-baud]
// [--reconnect-ms N]: the session conformance tool (docs/conformance.md section 8). Reads command
// packets as canonical JSON lines on stdin (or {"link": "idle"}: get the device to idle), runs them
// in order over the connection and prints one result line per command; every other packet received
// (and every skip run) is printed as its canonical line, in arrival order. The steps of getting
// through (a baud rate searched, a lost port reopened) are "link: ..." lines on stderr.
// Exit 0 when every line ran, 1 when a line was bad (reported on stderr with its number and
// skipped), 2 for usage or connection errors.
//
// Input lines and options follow the one table of docs/conformance.md section 8 (the same in every
// language): a line longer than kMaxLine bytes, or not UTF-8, is a bad line (read past in bounded
// memory); a blank line (only space, tab, CR, LF) is skipped; anything else is a command or link
// line. Bounded whatever the device sends (issue 37): each read asks for at most 65536 bytes and
// is fed and printed before the next; the received bytes are kept only from the session's
// retain_from() on (the pending skip piece, under 65536 bytes, and the parser's candidate).
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unistd.h>
#include <optional>
#include <string>
#include <vector>

#include "protopkg/json_reader.hpp"
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

/// A violation of the option table: exactly one line "PROG: TEXT", exit status 2.
int option_error(const std::string &text) {
    std::fprintf(stderr, "%s: %s\n", kProg, text.c_str());
    return 2;
}

/// A decimal integer of ASCII digits only (leading zeros allowed; no sign, no spaces) from low to
/// high.
bool int_option(const std::string &text, long low, long high, long &out) {
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) {
        return false;
    }
    const std::size_t first = text.find_first_not_of('0');
    if (first != std::string::npos && text.size() - first > 12) {
        return false;
    }
    out = first == std::string::npos ? 0 : std::atol(text.c_str() + first);
    return out >= low && out <= high;
}

/// The protocol's link baud rates (every device's, from the spec's link.baud_rates as generated
/// into devices.hpp), ascending, each once.
std::vector<std::uint32_t> baud_rates() {
    std::vector<std::uint32_t> out;
    for (const protopkg::Device d : protopkg::kDevices) {
        for (const std::uint32_t r : protopkg::device_baud_rates(d)) {
            out.push_back(r);
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

constexpr long kMaxListenMs = 3600000;

/// A link line: 1 for {"link":"idle"}, 2 for {"link":"listen","ms":M} (with ms), -1 for a
/// malformed one (why), 0 for anything else (a command line). A JSON object with a "link" member is
/// a link line.
int link_line(const std::string &line, long &ms, std::string &why) {
    if (line.find("\"link\"") == std::string::npos) {
        return 0;
    }
    protopkg::json::Value v;
    std::string error;
    if (!protopkg::json::parse(line, v, error) || v.type != protopkg::json::Value::Type::object) {
        return 0;
    }
    const protopkg::json::Value *link = v.find("link");
    if (link == nullptr) {
        return 0;
    }
    const bool is_string = link->type == protopkg::json::Value::Type::string;
    if (v.keys.size() == 1 && is_string && link->text == "idle") {
        return 1;
    }
    const protopkg::json::Value *m = v.find("ms");
    if (v.keys.size() == 2 && is_string && link->text == "listen" && m != nullptr) {
        const std::string &t = m->text;
        if (m->type == protopkg::json::Value::Type::number &&
            (t == "-0" || int_option(t, 0, kMaxListenMs, ms))) {
            if (t == "-0") {
                ms = 0;
            }
            return 2;
        }
        why = "\"ms\" must be an integer from 0 to 3600000";
        return -1;
    }
    why = "expected {\"link\":\"idle\"} or {\"link\":\"listen\",\"ms\":M}";
    return -1;
}

/// Standard input as lines, in bounded memory: a line longer than kMaxLine bytes (without its
/// newline) is reported as too long, its bytes past the limit read and dropped.
class LineReader {
  public:
    static constexpr std::size_t kMaxLine = 1048576;

    /// The next line (without its newline); false at the end of input. too_long: the line was
    /// longer than kMaxLine (line then holds its first kMaxLine bytes).
    bool next(std::string &line, bool &too_long) {
        line.clear();
        too_long = false;
        bool any = false;
        for (;;) {
            if (pos_ == len_) {
                if (eof_) {
                    return any;
                }
                const long n = read_some();
                if (n <= 0) {
                    eof_ = true;
                    return any;
                }
                pos_ = 0;
                len_ = static_cast<std::size_t>(n);
            }
            any = true;
            const char *start = buf_.data() + pos_;
            const void *nl = std::memchr(start, '\n', len_ - pos_);
            const std::size_t n =
                nl != nullptr ? static_cast<std::size_t>(static_cast<const char *>(nl) - start) : len_ - pos_;
            if (!too_long) {
                if (line.size() + n > kMaxLine) {
                    line.append(start, kMaxLine - line.size());
                    too_long = true;
                } else {
                    line.append(start, n);
                }
            }
            pos_ += n;
            if (nl != nullptr) {
                ++pos_;
                return true;
            }
        }
    }

  private:
    long read_some() {
        for (;;) {
            const ssize_t n = ::read(0, buf_.data(), buf_.size());
            if (n >= 0 || errno != EINTR) {
                return static_cast<long>(n);
            }
        }
    }
    std::vector<char> buf_ = std::vector<char>(65536);
    std::size_t pos_ = 0;
    std::size_t len_ = 0;
    bool eof_ = false;
};

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

// The command line's options.
struct Args {
    std::string connect;
    long timeout_ms = protopkg::kDefaultTimeoutMs;
    long baud = 115200;
    long reconnect_ms = 0;
    bool auto_baud = false;
    std::optional<protopkg::Device> device_id;
};

constexpr int kArgsRead = -1;

// One option's value into args: kArgsRead, or the exit status (the message printed).
int option_value(const std::string &name, const std::string &value, Args &args) {
    if (name == "--connect") {
        args.connect = value;
    } else if (name == "--timeout-ms") {
        if (!int_option(value, 1, 600000, args.timeout_ms)) {
            return option_error("--timeout-ms: expected an integer from 1 to 600000, got " + value);
        }
    } else if (name == "--baud") {
        const std::vector<std::uint32_t> rates = baud_rates();
        if (!int_option(value, 1, 100000000, args.baud) ||
            std::find(rates.begin(), rates.end(), static_cast<std::uint32_t>(args.baud)) == rates.end()) {
            std::string all;
            for (const std::uint32_t r : rates) {
                all += (all.empty() ? "" : ", ") + std::to_string(r);
            }
            return option_error("--baud: " + value + " is not a baud rate of " + protopkg::kProtocolName +
                                " devices (" + all + ")");
        }
    } else if (name == "--reconnect-ms") {
        if (!int_option(value, 1, 3600000, args.reconnect_ms)) {
            return option_error("--reconnect-ms: expected an integer from 1 to 3600000, got " + value);
        }
    } else {
        args.device_id = protopkg::device_from_name(value.c_str());
        if (!args.device_id) {
            std::string all;
            for (protopkg::Device d : protopkg::kDevices) {
                all += std::string(all.empty() ? "" : ", ") + protopkg::device_name(d);
            }
            return usage_error("unknown device '" + value + "' (one of: " + all + ")");
        }
    }
    return kArgsRead;
}

// Every option checked before anything is opened or sent: kArgsRead, or the exit status.
int read_args(const std::vector<std::string> &argv, Args &args) {
    for (const std::string &a : argv) {
        if (a == "-h" || a == "--help") {
            std::printf("%s\n", kUsage);
            return 0;
        }
    }
    for (std::size_t i = 0; i < argv.size();) {
        const std::string a = argv[i];
        const std::size_t eq = a.find('=');
        const std::string name = a.substr(0, eq);
        std::string value;
        if (a == "--auto-baud") {
            args.auto_baud = true;
            ++i;
            continue;
        }
        if (name != "--connect" && name != "--timeout-ms" && name != "--device" && name != "--baud" &&
            name != "--reconnect-ms") {
            return usage_error("unknown argument '" + a + "'");
        }
        if (eq == std::string::npos) {
            if (i + 1 >= argv.size()) {
                if (name == "--connect") {
                    return option_error("--connect ADDRESS is required");
                }
                return usage_error(name + " needs a value");
            }
            value = argv[i + 1];
            ++i;
        } else {
            value = a.substr(eq + 1);
        }
        ++i;
        const int status = option_value(name, value, args);
        if (status != kArgsRead) {
            return status;
        }
    }
    if (args.connect.empty()) {
        return option_error("--connect ADDRESS is required");
    }
    return kArgsRead;
}

// The transport that keeps every byte read until the parser has decided on it: the received bytes
// not yet decided on, to print skip runs (from stream offset base).
struct Recording : protopkg::Transport {
    protopkg::Transport &inner;
    std::vector<std::uint8_t> hist;
    std::uint64_t base = 0;
    protopkg::Connection *device = nullptr;
    explicit Recording(protopkg::Transport &t) : inner(t) {}
    bool write(const std::uint8_t *data, std::size_t size, protopkg::ErrorText &err) override {
        return inner.write(data, size, err);
    }
    long read(std::uint8_t *buffer, std::size_t capacity, std::int64_t timeout_ms,
              protopkg::ErrorText &err) override {
        // Bounded: the session keeps retain_from() within a skip piece and a candidate of
        // the stream's end; the bytes before it are dropped once they are half of what is kept
        // (each byte moved a bounded number of times).
        const std::uint64_t keep = device->session().retain_from();
        if (keep > base && (keep - base) * 2 >= hist.size()) {
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
    // The event's line, its skipped bytes read from what is kept.
    std::string line(const protopkg::SessionEvent &e,
                     const std::optional<protopkg::Device> &device_id) const {
        return protopkg::session_event_line(
            e, device_id, [&](std::uint64_t offset) { return hist.data() + (offset - base); });
    }
};

// A link line ({"link":"idle"}, {"link":"listen","ms":M}) or a command line, not blank and UTF-8:
// 0 done, 1 a bad line (reported, the next one runs), 2 the connection is gone (reported: stop).
int run_line(protopkg::Connection &dev, const Recording &recording, const std::string &line,
             unsigned long number, const std::optional<protopkg::Device> &device_id) {
    long listen_ms = 0;
    std::string why;
    const int link_kind = link_line(line, listen_ms, why);
    if (link_kind < 0) {
        std::fprintf(stderr, "%s: line %lu: %s\n", kProg, number, why.c_str());
        return 1;
    }
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
        print(recording.line(e, device_id));
        return 0;
    }
    if (link_kind == 2) {
        protopkg::ErrorText err;
        if (!dev.listen(listen_ms, &err)) {
            std::fprintf(stderr, "%s: %s\n", kProg, err.c_str());
            return 2;
        }
        print("{\"line\":" + std::to_string(number) + ",\"listened\":" + std::to_string(listen_ms) + "}");
        return 0;
    }
    protopkg::Call call;
    bool ran = false;
    std::string error;
    const bool ok = protopkg::with_command_from_line(line, error, [&](const auto &command) {
        protopkg::StartOptions start;
        start.tag = number;
        call = dev.run(command, start);
        ran = true;
    });
    if (!ok && !ran) {
        std::fprintf(stderr, "%s: line %lu: %s\n", kProg, number, error.c_str());
        return 1;
    }
    if (!call.note.empty()) { // the first unknown-command NACK: the connected model is another one
        std::fprintf(stderr, "%s: %s\n", kProg, call.note.c_str());
        std::fflush(stderr);
    }
    if (call.io_error) {
        if (call.lost && dev.connected()) { // reconnected: the command was lost with the port
            print(lost_line(number, call.io.str()));
            return 0;
        }
        std::fprintf(stderr, "%s: %s\n", kProg, call.io.c_str());
        return 2;
    }
    return 0;
}

} // namespace

int main(int argc, char **argv) {
    Args args;
    const int read = read_args(std::vector<std::string>(argv + 1, argv + argc), args);
    if (read != kArgsRead) {
        return read;
    }
#ifdef SIGPIPE
    std::signal(SIGPIPE, SIG_IGN);
#endif
    std::string error;
    std::unique_ptr<protopkg::Transport> transport = protopkg::open_transport(args.connect, args.baud, error);
    if (!transport) {
        std::fprintf(stderr, "%s: %s\n", kProg, error.c_str());
        return 2;
    }
    protopkg::Session<1>::Options options;
    options.device = args.device_id;
    options.timeout_ms = args.timeout_ms;
    Recording recording(*transport);
    protopkg::Connection dev(recording, options);
    recording.device = &dev;
    dev.on_event([&](const protopkg::SessionEvent &e) {
        const std::string line = recording.line(e, args.device_id);
        std::fwrite(line.data(), 1, line.size(), stdout);
        std::fputc('\n', stdout);
        std::fflush(stdout);
    });
    protopkg::LinkOptions link;
    link.log = [](const std::string &text) {
        std::fprintf(stderr, "%s\n", text.c_str());
        std::fflush(stderr);
    };
    link.reconnect_ms = args.reconnect_ms;
    dev.link_options(link);
    if (args.auto_baud && recording.baud() != 0) {
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
    LineReader input;
    bool too_long = false;
    while (input.next(line, too_long)) {
        ++number;
        if (too_long) {
            std::fprintf(stderr, "%s: line %lu: longer than %zu bytes\n", kProg, number,
                         LineReader::kMaxLine);
            status = 1;
            continue;
        }
        if (!utf8(line)) {
            std::fprintf(stderr, "%s: line %lu: not UTF-8\n", kProg, number);
            status = 1;
            continue;
        }
        if (blank(line)) {
            continue;
        }
        const int outcome = run_line(dev, recording, line, number, args.device_id);
        if (outcome == 2) {
            return 2;
        }
        status = outcome != 0 ? outcome : status;
    }
    dev.close();
    return status;
}
