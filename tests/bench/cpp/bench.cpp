// Benchmark of the generated C++ package mipcodec (issue 8): a plain timed loop.
//
//   bench DIR [--passes N] [--stream NAME] [--mode frame|decode]
//
// For every stream DIR/<name>.bin (sidecar DIR/<name>.json) it times, best of N passes over the
// whole file in memory (read once, not timed):
//   lang=cpp mode=frame   StreamParser::feed + flush: every packet reported, garbage skipped
//   lang=cpp mode=decode  the same, plus FieldIterator and decode_field of every field
// and prints `BENCH lang=cpp stream=<name> mode=<mode> packets=N bytes=B seconds=S` lines. The
// packet and field counts are checked against the sidecar (exit 1 on mismatch); a checksum of
// the decoded values is printed to stderr so the work cannot be optimised away.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "mipcodec/mipcodec.hpp"

namespace {

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

enum class Mode { frame, decode };

void run_pass(const Stream &s, Mode mode, Counts &c) {
    c = Counts{};
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
        std::fprintf(stderr, "usage: bench DIR [--passes N] [--stream NAME] [--mode frame|decode]\n");
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
        for (Mode m : {Mode::frame, Mode::decode}) {
            const char *mode_name = m == Mode::frame ? "frame" : "decode";
            if (only_mode != nullptr && std::strcmp(only_mode, mode_name) != 0) {
                continue;
            }
            double best = 1e30;
            Counts c;
            for (int k = 0; k < passes; ++k) {
                const auto t0 = std::chrono::steady_clock::now();
                run_pass(s, m, c);
                const std::chrono::duration<double> dt = std::chrono::steady_clock::now() - t0;
                if (dt.count() < best) {
                    best = dt.count();
                }
            }
            if (c.packets != s.packets) {
                std::fprintf(stderr, "bench: %s %s: %llu packets, the sidecar says %llu\n", name, mode_name,
                             static_cast<unsigned long long>(c.packets), static_cast<unsigned long long>(s.packets));
                failed = 1;
            }
            if (m == Mode::decode && (c.fields != s.fields || c.errors != 0)) {
                std::fprintf(stderr, "bench: %s decode: %llu fields (%llu errors), the sidecar says %llu\n", name,
                             static_cast<unsigned long long>(c.fields), static_cast<unsigned long long>(c.errors),
                             static_cast<unsigned long long>(s.fields));
                failed = 1;
            }
            std::printf("BENCH lang=cpp stream=%s mode=%s packets=%llu bytes=%zu seconds=%.6f\n", name, mode_name,
                        static_cast<unsigned long long>(c.packets), s.data.size(), best);
            std::fprintf(stderr, "bench: %s %s check %016llx\n", name, mode_name,
                         static_cast<unsigned long long>(c.check));
            std::fflush(stdout);
        }
    }
    return failed;
}
