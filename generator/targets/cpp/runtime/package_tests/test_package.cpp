// Tests of a package's generated code through the runtime, for any protocol: field dispatch
// (every plain layout loads like its checked decode) and JSON lines of a random stream back to its
// bytes. Copied into every package (tests/test_package.cpp); in place, run on the stub package of
// tests/package/.
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace {

namespace pkg = ::protopkg;
using Bytes = std::vector<std::uint8_t>;

/// A valid packet carrying one raw field with `n` data bytes.
Bytes packet(std::uint8_t set, std::uint8_t descriptor, std::size_t n) {
    pkg::PacketBuilder b(set);
    Bytes data(n);
    for (std::size_t i = 0; i < n; ++i) {
        data[i] = static_cast<std::uint8_t>(i * 7 + 1);
    }
    EXPECT_EQ(b.add_raw_field(descriptor, data.data(), data.size()), pkg::EncodeError::none);
    const pkg::PacketView p = b.finish();
    return Bytes(p.data, p.data + p.size);
}

TEST(JsonLines, RandomStreamRoundTrip) {
    Bytes input;
    std::uint32_t seed = 12345;
    auto next = [&]() {
        seed = seed * 1103515245u + 12345u;
        return (seed >> 16) & 0x7FFF;
    };
    for (int i = 0; i < 60; ++i) {
        const Bytes p = packet(static_cast<std::uint8_t>(1 + next() % 200), static_cast<std::uint8_t>(next()),
                               next() % 40);
        switch (next() % 4) {
        case 0:
            input.insert(input.end(), p.begin(), p.end());
            break;
        case 1: // corrupted
            input.insert(input.end(), p.begin(), p.end());
            input[input.size() - 1 - next() % p.size()] ^= 0x40;
            break;
        case 2: // cut short
            input.insert(input.end(), p.begin(), p.begin() + static_cast<long>(next() % p.size()));
            break;
        default: // random bytes, sync bytes included
            for (unsigned k = next() % 9; k > 0; --k) {
                input.push_back(next() % 3 == 0 ? pkg::kSync[next() % pkg::kSyncSize]
                                                : static_cast<std::uint8_t>(next()));
            }
        }
    }
    // the JSON lines of a stream of packets, corrupted packets and stray bytes encode back to it
    const std::vector<std::string> lines = protopkg_test::decode_lines(input, 5, nullptr);
    EXPECT_EQ(protopkg_test::encode_lines(lines), input);
}

struct CountingVisitor {
    int decoded = 0;
    int undecoded = 0;
    std::string last_error;
    template <class T> void field(const T &) {
        ++decoded;
    }
    void raw(const pkg::DecodeError &err) {
        ++undecoded;
        last_error = err.text().str();
    }
};

TEST(Dispatch, ReadmeExampleShape) {
    // A field nobody defines in an unassigned set: raw, with a dispatch error.
    const Bytes input = packet(0x01, 0x7A, 2);
    pkg::StreamParser parser;
    CountingVisitor counter;
    auto on_event = [&](const pkg::StreamEvent &e) {
        if (e.kind != pkg::StreamEvent::Kind::packet) {
            return;
        }
        pkg::FieldIterator it(e.packet);
        pkg::FieldEntry f;
        while (it.next(f)) {
            if (f.kind == pkg::FieldEntry::Kind::field) {
                pkg::decode_field(e.packet.set(), f.descriptor, f.data, f.size, std::nullopt, counter);
            }
        }
    };
    parser.feed(input.data(), input.size(), on_event);
    parser.flush(on_event);
    EXPECT_EQ(counter.decoded + counter.undecoded, 1);
    if (counter.undecoded == 1) {
        EXPECT_FALSE(counter.last_error.empty());
    }
}

// Every layout that decodes by straight loads (Plain<T>, decode_field's fast path): loading
// kSize distinct bytes and encoding the value back gives the same bytes, and so does the checked
// Codec<T>::read, which must also take exactly those bytes.
struct PlainLayoutCheck {
    int plain = 0;
    std::vector<std::string> failures;

    template <class T, class... Rest> void operator()(pkg::Layouts<T, Rest...>) {
        one<T>();
        (one<Rest>(), ...);
    }
    template <class T> void one() {
        if constexpr (pkg::Plain<T>::kPlain) {
            constexpr std::size_t n = pkg::Plain<T>::kSize;
            std::uint8_t bytes[n + 1] = {};
            for (std::size_t i = 0; i < n; ++i) {
                bytes[i] = static_cast<std::uint8_t>(0x5A + 37 * i);
            }
            T straight;
            pkg::Plain<T>::load(bytes, straight);
            T checked{};
            pkg::Reader r(bytes, n);
            pkg::DecodeError err;
            const bool ok = pkg::Codec<T>::read(r, checked, err) && r.left() == 0;
            std::uint8_t out1[pkg::kMaxFieldData + 1];
            std::uint8_t out2[pkg::kMaxFieldData + 1];
            std::size_t w1 = 0;
            std::size_t w2 = 0;
            const bool same = pkg::encode(straight, out1, sizeof out1, w1) == pkg::EncodeError::none &&
                              pkg::encode(checked, out2, sizeof out2, w2) == pkg::EncodeError::none &&
                              w1 == n && w2 == n && std::memcmp(out1, bytes, n) == 0 &&
                              std::memcmp(out2, bytes, n) == 0;
            if (!ok || !same) {
                failures.push_back(T::kName);
            }
            ++plain;
        }
    }
};

TEST(Dispatch, PlainLayoutsLoadLikeTheCheckedDecode) {
    PlainLayoutCheck check;
    unsigned cases = 0;
    for (unsigned c = 2; pkg::visit_case(c, check); ++c) {
        ++cases;
    }
    EXPECT_GT(cases, 0u);
    EXPECT_GT(check.plain, 0);
    EXPECT_EQ(check.failures, std::vector<std::string>{});
}

} // namespace
