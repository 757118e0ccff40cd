// Benchmark of the generated C++ package mipcodec (issue 8): a plain timed loop.
//
//   bench DIR [--passes N] [--stream NAME]
//         [--mode bulk|frame|decode|decode-cached|decode-straight|session-ingest|session-roundtrip|none]
//
// For every stream DIR/<name>.bin (sidecar DIR/<name>.json) it times, best of N passes over the
// whole file in memory (read once, not timed):
//   lang=cpp mode=bulk    one memcpy of the whole stream into another buffer (allocated and written
//                         once before timing): the limit the parsers' rows are divided by
//   lang=cpp mode=frame   StreamParser::feed + flush: every packet reported, garbage skipped
//   lang=cpp mode=decode  the same, plus the typed decode of every field: FieldIterator and
//                         decode_field of every field (the fastest C++ path on these streams,
//                         docs/benchmarks.md "Issue 38")
//   lang=cpp mode=decode-cached  the typed decode through a LayoutCache (mipcodec/packets.hpp,
//                         issue 38): the packet's cached shape, else the straight-line decoder of
//                         its set; an entry it leaves goes to decode_field
//   lang=cpp mode=decode-straight  the same without the cache: mipcodec::decode_packet
//   lang=cpp mode=session-ingest  the stream fed to a Session with one command pending whose reply
//                         never comes (deadline far away): every packet routed to a per-packet
//                         handler that decodes its fields as `decode` does
// and once, stream=loopback-tcp mode=session-roundtrip: ping round trips through the blocking
// API (api::base::ping over a Connection on a loopback TCP socket) to a responder thread that
// answers each ping with its ack (bytes = bytes sent + received);
// (mode none: nothing, no line; with --stream, the program's fixed cost that instruction counts
// subtract) and prints `BENCH lang=cpp stream=<name> mode=<mode> packets=N bytes=B seconds=S` lines. The
// packet and field counts are checked against the sidecar (exit 1 on mismatch); a checksum of
// the decoded values is printed to stderr so the work cannot be optimised away.
#include <time.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <type_traits>
#include <thread>
#include <vector>

#include "mipcodec/commands.hpp"
#include "mipcodec/mipcodec.hpp"
#include "mipcodec/packets.hpp"
#include "mipcodec/session.hpp"
#include "mipcodec/transport_posix.hpp"

namespace {

// The CPU time of this thread: what a pass costs, without the scheduler ticks other tasks take on
// a shared machine (docs/benchmarks.md). Round trips over TCP stay on the wall clock.
double cpu_now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

const char *const kStreams[] = {"accel_gyro", "mixed", "accel_gyro_garbage", "mixed_garbage"};

struct Stream {
    std::vector<std::uint8_t> data;
    std::uint64_t packets = 0;
    std::uint64_t fields = 0;
};

struct Counts {
    std::uint64_t packets = 0;
    std::uint64_t fields = 0;
    std::uint64_t errors = 0;
    std::uint64_t check = 0;
};

bool read_file(const std::string &path, std::vector<std::uint8_t> &out) {
    std::ifstream f(path, std::ios::binary);
    if (!f) {
        return false;
    }
    out.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    return true;
}

bool json_u64(const std::string &json, const char *key, std::uint64_t &out) {
    const std::string pat = std::string("\"") + key + "\":";
    const auto p = json.find(pat);
    if (p == std::string::npos) {
        return false;
    }
    out = std::strtoull(json.c_str() + p + pat.size(), nullptr, 10);
    return true;
}

bool load(const std::string &dir, const char *name, Stream &s) {
    std::vector<std::uint8_t> json;
    const std::string side = dir + "/" + name + ".json";
    if (!read_file(side, json)) {
        std::fprintf(stderr, "bench: cannot read %s\n", side.c_str());
        return false;
    }
    const std::string text(json.begin(), json.end());
    if (!json_u64(text, "packets", s.packets) || !json_u64(text, "fields", s.fields)) {
        std::fprintf(stderr, "bench: %s has no packets/fields counts\n", side.c_str());
        return false;
    }
    const std::string bin = dir + "/" + name + ".bin";
    if (!read_file(bin, s.data)) {
        std::fprintf(stderr, "bench: cannot read %s\n", bin.c_str());
        return false;
    }
    return true;
}

// Consumes a decoded value: its first 4 bytes (the first float of scaled accel / gyro, ...), as a
// reader of one value would load them (an 8-byte load over two 4-byte stores would stall on store
// forwarding and measure that instead of the decoder).
struct Consume {
    Counts &c;
    template <class T> void field(const T &value) {
        std::uint32_t word = 0;
        if constexpr (std::is_trivially_copyable_v<T>) {
            std::memcpy(&word, &value, sizeof(T) < sizeof word ? sizeof(T) : sizeof word);
        } else {
            word = sizeof(T);
        }
        c.check += word ^ T::kDescriptor;
        ++c.fields;
    }
    void raw(const mipcodec::DecodeError &) {
        ++c.errors;
    }
};

enum class Mode { bulk, frame, decode, decode_cached, decode_straight, session_ingest };

// Called through a volatile pointer so that the compiler cannot drop or split the copy.
void *(*volatile bulk_copy)(void *, const void *, std::size_t) = std::memcpy;

void run_pass(const Stream &s, std::vector<std::uint8_t> &into, Mode mode, Counts &c) {
    c = Counts{};
    if (mode == Mode::bulk) {
        bulk_copy(into.data(), s.data.data(), s.data.size());
        c.packets = s.packets;
        c.check += into.empty() ? 0 : into.back();
        return;
    }
    mipcodec::StreamParser parser;
    if (mode == Mode::frame) {
        auto on = [&c](const mipcodec::StreamEvent &e) {
            if (e.kind == mipcodec::StreamEvent::Kind::packet) {
                ++c.packets;
                c.check += e.packet.size + e.packet.set();
            }
        };
        parser.feed(s.data.data(), s.data.size(), on);
        parser.flush(on);
        return;
    }
    const std::optional<mipcodec::Device> any;
    if (mode == Mode::session_ingest) {
        // One command pending (a ping whose ack never comes) for the whole stream.
        mipcodec::Session<>::Options options;
        options.timeout_ms = std::int64_t{1} << 40;
        mipcodec::Session<> session(options);
        session.on_packet([&c, &any](const mipcodec::PacketView &packet, std::uint64_t) {
            ++c.packets;
            const std::uint8_t set = packet.set();
            mipcodec::FieldIterator fields(packet);
            mipcodec::FieldEntry entry;
            while (fields.next(entry)) {
                if (entry.kind != mipcodec::FieldEntry::Kind::field) {
                    ++c.errors;
                    continue;
                }
                mipcodec::decode_field(set, entry.descriptor, entry.data, entry.size, any, Consume{c});
            }
        });
        session.start(mipcodec::base::Ping{}, 0);
        auto ignore = [](const mipcodec::SessionEvent &) {};
        session.feed(s.data.data(), s.data.size(), 1, ignore);
        session.close(2, ignore);
        if (session.pending() != 1) {
            ++c.errors;
        }
        return;
    }
    if (mode == Mode::decode_cached || mode == Mode::decode_straight) {
        // The straight-line decoders (through the layout cache for `decode-cached`); what they leave (a
        // field with per-device variants, anything they cannot decode) goes to the general
        // dispatch, as a program that handles every field would.
        static mipcodec::AnyPacket packet;
        static mipcodec::LayoutCache cache;
        cache.clear();
        const bool cached = mode == Mode::decode_cached;
        auto on = [&c, &any, cached](const mipcodec::StreamEvent &e) {
            if (e.kind != mipcodec::StreamEvent::Kind::packet) {
                return;
            }
            ++c.packets;
            const std::uint8_t set = e.packet.set();
            auto other = [&c, &any, set](const mipcodec::FieldEntry &entry) {
                if (entry.kind != mipcodec::FieldEntry::Kind::field) {
                    ++c.errors;
                    return;
                }
                mipcodec::decode_field(set, entry.descriptor, entry.data, entry.size, any, Consume{c});
            };
            const mipcodec::PacketIndex *index = cached ? cache.decode(e.packet, packet, other)
                                                        : mipcodec::decode_packet(e.packet, packet, other);
            if (index != nullptr) {
                packet.visit([&c](const auto &value) { Consume{c}.field(value); });
            }
        };
        parser.feed(s.data.data(), s.data.size(), on);
        parser.flush(on);
        return;
    }
    auto on = [&c, &any](const mipcodec::StreamEvent &e) {
        if (e.kind != mipcodec::StreamEvent::Kind::packet) {
            return;
        }
        ++c.packets;
        const std::uint8_t set = e.packet.set();
        mipcodec::FieldIterator fields(e.packet);
        mipcodec::FieldEntry entry;
        while (fields.next(entry)) {
            if (entry.kind != mipcodec::FieldEntry::Kind::field) {
                ++c.errors;
                continue;
            }
            mipcodec::decode_field(set, entry.descriptor, entry.data, entry.size, any, Consume{c});
        }
    };
    parser.feed(s.data.data(), s.data.size(), on);
    parser.flush(on);
}

// Answers every complete packet read from `fd` with the ack of its first field's descriptor.
void responder(int fd) {
    std::vector<std::uint8_t> buf;
    std::uint8_t chunk[512];
    for (;;) {
        const ssize_t n = ::read(fd, chunk, sizeof chunk);
        if (n <= 0) {
            break;
        }
        buf.insert(buf.end(), chunk, chunk + n);
        while (buf.size() >= 4 && buf.size() >= std::size_t{4} + buf[3] + 2) {
            const std::size_t total = std::size_t{4} + buf[3] + 2;
            mipcodec::PacketBuilder b(buf[2]);
            mipcodec::reserved::AckNack ack{};
            ack.command_descriptor = buf[5];
            b.add(ack);
            const mipcodec::PacketView p = b.finish();
            if (::write(fd, p.data, p.size) != static_cast<ssize_t>(p.size)) {
                return;
            }
            buf.erase(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(total));
        }
    }
}

// Ping round trips over loopback TCP through the blocking API; false on a failure.
bool roundtrip(int trips, int passes) {
    const int srv = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof addr;
    if (srv < 0 || ::bind(srv, reinterpret_cast<sockaddr *>(&addr), sizeof addr) != 0 ||
        ::listen(srv, 1) != 0 || ::getsockname(srv, reinterpret_cast<sockaddr *>(&addr), &len) != 0) {
        std::fprintf(stderr, "bench: cannot listen on loopback\n");
        return false;
    }
    std::thread server([srv]() {
        const int fd = ::accept(srv, nullptr, nullptr);
        if (fd >= 0) {
            int one = 1;
            ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
            responder(fd);
            ::close(fd);
        }
    });
    std::string error;
    std::unique_ptr<mipcodec::Transport> t =
        mipcodec::open_tcp("tcp:127.0.0.1:" + std::to_string(ntohs(addr.sin_port)), error);
    bool ok = t != nullptr;
    double best = 1e30;
    std::uint64_t bytes = 0;
    if (ok) {
        mipcodec::Connection connection(*t);
        for (int k = 0; k < passes && ok; ++k) {
            const auto t0 = std::chrono::steady_clock::now();
            for (int i = 0; i < trips; ++i) {
                const mipcodec::Call call = mipcodec::api::base::ping::call(connection);
                if (!call.ok()) {
                    std::fprintf(stderr, "bench: ping %d: %s\n", i, call.describe().c_str());
                    ok = false;
                    break;
                }
                bytes = static_cast<std::uint64_t>(trips) * (8 + call.result.packet_size);
            }
            const std::chrono::duration<double> dt = std::chrono::steady_clock::now() - t0;
            best = dt.count() < best ? dt.count() : best;
        }
        t.reset(); // closes the socket: the responder ends
    } else {
        std::fprintf(stderr, "bench: %s\n", error.c_str());
    }
    server.join();
    ::close(srv);
    if (ok) {
        std::printf(
            "BENCH lang=cpp stream=loopback-tcp mode=session-roundtrip packets=%d bytes=%llu seconds=%.6f\n",
            trips, static_cast<unsigned long long>(bytes), best);
        std::fflush(stdout);
    }
    return ok;
}

} // namespace

int main(int argc, char **argv) {
    const char *dir = nullptr;
    int passes = 5;
    const char *only = nullptr;
    const char *only_mode = nullptr;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--passes") == 0 && i + 1 < argc) {
            passes = std::atoi(argv[++i]);
        } else if (std::strcmp(argv[i], "--stream") == 0 && i + 1 < argc) {
            only = argv[++i];
        } else if (std::strcmp(argv[i], "--mode") == 0 && i + 1 < argc) {
            only_mode = argv[++i];
        } else if (dir == nullptr) {
            dir = argv[i];
        } else {
            dir = nullptr;
            break;
        }
    }
    if (dir == nullptr || passes < 1) {
        std::fprintf(
            stderr,
            "usage: bench DIR [--passes N] [--stream NAME] "
            "[--mode "
            "bulk|frame|decode|decode-cached|decode-straight|session-ingest|session-roundtrip|none]\n");
        return 2;
    }
    int failed = 0;
    for (const char *name : kStreams) {
        Stream s;
        if (only != nullptr && std::strcmp(only, name) != 0) {
            continue;
        }
        if (!load(dir, name, s)) {
            return 1;
        }
        std::vector<std::uint8_t> into(s.data.size()); // bulk's destination, written once
        for (Mode m : {Mode::bulk, Mode::frame, Mode::decode, Mode::decode_cached, Mode::decode_straight,
                       Mode::session_ingest}) {
            const char *mode_name = m == Mode::bulk              ? "bulk"
                                    : m == Mode::frame           ? "frame"
                                    : m == Mode::decode          ? "decode"
                                    : m == Mode::decode_cached   ? "decode-cached"
                                    : m == Mode::decode_straight ? "decode-straight"
                                                                 : "session-ingest";
            if (only_mode != nullptr && std::strcmp(only_mode, mode_name) != 0) {
                continue;
            }
            double best = 1e30;
            Counts c;
            for (int k = 0; k < passes; ++k) {
                const double t0 = cpu_now();
                run_pass(s, into, m, c);
                const double dt = cpu_now() - t0;
                if (dt < best) {
                    best = dt;
                }
            }
            if (c.packets != s.packets) {
                std::fprintf(stderr, "bench: %s %s: %llu packets, the sidecar says %llu\n", name, mode_name,
                             static_cast<unsigned long long>(c.packets),
                             static_cast<unsigned long long>(s.packets));
                failed = 1;
            }
            if (m == Mode::bulk && into != s.data) {
                std::fprintf(stderr, "bench: %s bulk: the copy differs from the stream\n", name);
                failed = 1;
            }
            if (m != Mode::frame && m != Mode::bulk && (c.fields != s.fields || c.errors != 0)) {
                std::fprintf(stderr, "bench: %s %s: %llu fields (%llu errors), the sidecar says %llu\n", name,
                             mode_name, static_cast<unsigned long long>(c.fields),
                             static_cast<unsigned long long>(c.errors),
                             static_cast<unsigned long long>(s.fields));
                failed = 1;
            }
            std::printf("BENCH lang=cpp stream=%s mode=%s packets=%llu bytes=%zu seconds=%.9f\n", name,
                        mode_name, static_cast<unsigned long long>(c.packets), s.data.size(), best);
            std::fprintf(stderr, "bench: %s %s check %016llx\n", name, mode_name,
                         static_cast<unsigned long long>(c.check));
            std::fflush(stdout);
        }
    }
    if (only == nullptr && (only_mode == nullptr || std::strcmp(only_mode, "session-roundtrip") == 0) &&
        !roundtrip(2000, passes > 3 ? 3 : passes)) {
        failed = 1;
    }
    return failed;
}
