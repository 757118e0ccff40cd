// Fuzz target `parser` (C++): the input format and the checks of tests/fuzz/c/fuzz_parser.c,
// through the header-only C++ API: StreamParser (whole and in chunks), FieldIterator,
// decode_field with a visitor (no device and each device), the typed encoder (encode<T>),
// write_packet_json / write_skip_json into a string and into a small truncating sink,
// encode_json_line, SampleTracker; the stream is also wrapped into a packet by PacketBuilder.
// Built as part of fuzz_targets.cpp (one translation unit for both targets; entry.cpp picks one).
#include "fuzz_common.hpp"

namespace fz_parser {

namespace pkg = fz::pkg;

enum class Kind { packet, skip, foreign };

struct Ev {
    Kind kind;
    std::uint64_t offset;
    std::uint64_t length;
    bool operator==(const Ev &o) const {
        return kind == o.kind && offset == o.offset && length == o.length;
    }
};

// Keeps at most kCap characters of what is written, and counts them all.
struct SmallSink {
    static constexpr std::size_t kCap = 24;
    char text[kCap];
    std::size_t len = 0;
    static void sink(void *context, const char *data, std::size_t size) {
        auto *s = static_cast<SmallSink *>(context);
        for (std::size_t i = 0; i < size; ++i) {
            if (s->len < kCap) {
                s->text[s->len] = data[i];
            }
            ++s->len;
        }
    }
};

struct FieldCheck {
    std::uint8_t set;
    std::uint8_t descriptor;
    const std::uint8_t *data;
    std::size_t size;

    template <class T> void field(const T &value) {
        FZ_CHECK(T::kDescriptor == descriptor, "%s has descriptor %u, decoded from %u", T::kName,
                 unsigned(T::kDescriptor), unsigned(descriptor));
        std::vector<std::uint8_t> buf(size);
        std::size_t written = 0;
        const pkg::EncodeError e = pkg::encode(value, buf.data(), buf.size(), written);
        FZ_CHECK(e == pkg::EncodeError::none, "re-encode of %s (set %u descriptor %u) failed: %s, data %s",
                 T::kName, unsigned(set), unsigned(descriptor), pkg::to_string(e),
                 fz::hex(data, size).c_str());
        FZ_CHECK(written == size && (size == 0 || std::memcmp(buf.data(), data, size) == 0),
                 "%s (set %u descriptor %u) re-encodes to %s, data %s", T::kName, unsigned(set),
                 unsigned(descriptor), fz::hex(buf.data(), written).c_str(), fz::hex(data, size).c_str());
        if (size > 0) {
            std::vector<std::uint8_t> shorter(size - 1);
            FZ_CHECK(pkg::encode(value, shorter.data(), shorter.size(), written) != pkg::EncodeError::none,
                     "%s encoded %zu bytes into %zu", T::kName, size, size - 1);
        }
    }
    void raw(const pkg::DecodeError &err) {
        const std::string text = err.text().str();
        FZ_CHECK(!text.empty(), "empty decode error text");
    }
};

void check_line(const std::uint8_t *bytes, std::size_t len, std::uint64_t offset, bool packet,
                const std::optional<pkg::Device> &device) {
    std::string line;
    SmallSink small;
    {
        pkg::JsonWriter w(pkg::string_sink, &line);
        pkg::JsonWriter s(SmallSink::sink, &small);
        if (packet) {
            pkg::write_packet_json(w, offset, pkg::PacketView{bytes, len}, device);
            pkg::write_packet_json(s, offset, pkg::PacketView{bytes, len}, device);
        } else {
            pkg::write_skip_json(w, offset, bytes, len);
            pkg::write_skip_json(s, offset, bytes, len);
        }
    }
    FZ_CHECK(small.len == line.size(), "line length %zu, %zu through the small sink", line.size(), small.len);
    const std::size_t n = line.size() < SmallSink::kCap ? line.size() : SmallSink::kCap;
    FZ_CHECK(std::memcmp(small.text, line.data(), n) == 0, "small sink is not a prefix: %s", line.c_str());
    for (std::size_t i = 0; i < line.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(line[i]);
        FZ_CHECK(c >= 0x20 && c < 0x7f, "byte 0x%02x at %zu of the line: %s", c, i, line.c_str());
    }
    std::vector<std::uint8_t> out;
    std::string error;
    FZ_CHECK(pkg::encode_json_line(line, out, error), "the decoded line does not encode (%s): %s",
             error.c_str(), line.c_str());
    FZ_CHECK(out.size() == len && std::memcmp(out.data(), bytes, len) == 0, "the line encodes to %s: %s",
             fz::hex(out.data(), out.size()).c_str(), line.c_str());
}

void check_packet(const std::uint8_t *bytes, std::size_t len, std::uint64_t offset,
                  const std::optional<pkg::Device> &device, pkg::SampleTracker &tracker) {
    const pkg::PacketView packet{bytes, len};
    FZ_CHECK(len >= pkg::kHeaderSize + pkg::kChecksumSize, "packet of %zu bytes", len);
    const std::size_t plen = packet.payload_size();
    FZ_CHECK(len == pkg::kHeaderSize + plen + pkg::kChecksumSize, "packet length %zu for payload %zu", len,
             plen);
    const auto sums = pkg::fletcher16(bytes, pkg::kHeaderSize + plen).bytes();
    FZ_CHECK(bytes[pkg::kHeaderSize + plen] == sums[0] && bytes[pkg::kHeaderSize + plen + 1] == sums[1],
             "bad checksum %s", fz::hex(bytes, len).c_str());
    const std::uint8_t *payload = packet.payload();
    const std::uint8_t set = packet.set();
    pkg::FieldIterator it(packet);
    pkg::FieldEntry e;
    std::size_t pos = 0;
    bool ended = false;
    static const std::vector<pkg::Device> all = fz::devices();
    while (it.next(e)) {
        FZ_CHECK(!ended, "an entry after the trailing entry");
        FZ_CHECK(e.payload_offset == pos, "entry at %zu, expected %zu", e.payload_offset, pos);
        if (e.kind == pkg::FieldEntry::Kind::field) {
            const std::uint8_t *head = payload + pos;
            const int adjust = pkg::field_length_adjust(set, head[pkg::kFieldDescriptorOffset]);
            FZ_CHECK(e.descriptor == head[pkg::kFieldDescriptorOffset] &&
                         e.data == head + pkg::kFieldHeaderSize,
                     "field entry at %zu", pos);
            FZ_CHECK(static_cast<int>(e.size) == int(head[pkg::kFieldLengthOffset]) - adjust,
                     "field size %zu", e.size);
            pos += pkg::kFieldHeaderSize + e.size;
            FZ_CHECK(pos <= plen, "field runs past the payload");
            FieldCheck check{set, e.descriptor, e.data, e.size};
            pkg::decode_field(set, e.descriptor, e.data, e.size, std::nullopt, check);
            for (const pkg::Device d : all) {
                pkg::decode_field(set, e.descriptor, e.data, e.size, std::optional<pkg::Device>(d), check);
            }
        } else {
            FZ_CHECK(e.data == payload + pos && e.size == plen - pos && e.size > 0,
                     "trailing entry does not hold the rest");
            FZ_CHECK(std::strlen(e.text().c_str()) > 0, "empty trailing message");
            pos = plen;
            ended = true;
        }
    }
    FZ_CHECK(pos == plen, "the entries cover %zu of %zu payload bytes", pos, plen);
    check_line(bytes, len, offset, true, device);
    if (const auto place = tracker.feed(packet)) {
        FZ_CHECK(place->shared_prefix <= plen, "shared prefix %zu of %zu", place->shared_prefix, plen);
    }
}

// Parses `stream` whole (plan == nullptr) or in chunks, checking every event against it.
template <class Each>
std::vector<Ev> events(const std::uint8_t *stream, std::size_t size, fz::Chunks *plan, Each &&each) {
    std::vector<Ev> out;
    auto on = [&](const pkg::StreamEvent &ev) {
        const bool packet = ev.kind == pkg::StreamEvent::Kind::packet;
        const bool foreign =
            ev.kind == pkg::StreamEvent::Kind::nmea || ev.kind == pkg::StreamEvent::Kind::rtcm;
        const std::uint64_t len = packet || foreign ? ev.packet.size : ev.count;
        const std::uint64_t expected = out.empty() ? 0 : out.back().offset + out.back().length;
        FZ_CHECK(out.empty() || packet || foreign || out.back().kind != Kind::skip, "two skip runs in a row");
        FZ_CHECK(ev.offset == expected, "event at %llu, expected %llu", (unsigned long long)ev.offset,
                 (unsigned long long)expected);
        FZ_CHECK(len > 0 && len <= size - ev.offset, "event length %llu", (unsigned long long)len);
        if (packet || foreign) {
            FZ_CHECK(std::memcmp(ev.packet.data, stream + ev.offset, len) == 0, "packet bytes differ at %llu",
                     (unsigned long long)ev.offset);
        }
        out.push_back(Ev{packet ? Kind::packet : foreign ? Kind::foreign : Kind::skip, ev.offset, len});
        if (!foreign) { // a foreign frame's line is not encoder input (docs/conformance.md section 5)
            each(packet, ev.offset, stream + ev.offset, static_cast<std::size_t>(len));
        }
    };
    pkg::StreamParser parser;
    if (plan == nullptr) {
        parser.feed(stream, size, on);
    } else {
        for (std::size_t pos = 0; pos < size;) {
            std::size_t n = plan->next();
            if (n > size - pos) {
                n = size - pos;
            }
            parser.feed(stream + pos, n, on);
            pos += n;
        }
    }
    parser.flush(on);
    const std::uint64_t end = out.empty() ? 0 : out.back().offset + out.back().length;
    FZ_CHECK(end == size, "the events cover %llu of %zu bytes", (unsigned long long)end, size);
    return out;
}

// The stream (n > 0) wrapped as (set = first byte, payload = the rest, at most the maximum) into
// a packet with a valid checksum; it must parse as exactly one packet (`each` sees it).
template <class Each>
std::vector<std::uint8_t> wrapped(const std::uint8_t *stream, std::size_t n, Each &&each) {
    const std::size_t plen = n - 1 < pkg::kMaxPayload ? n - 1 : pkg::kMaxPayload;
    pkg::PacketBuilder b(stream[0]);
    FZ_CHECK(b.append(stream + 1, plen) == pkg::EncodeError::none, "append of %zu bytes", plen);
    const pkg::PacketView p = b.finish();
    std::vector<std::uint8_t> built(p.data, p.data + p.size);
    const auto one = events(built.data(), built.size(), nullptr, each);
    FZ_CHECK(one.size() == 1 && one[0].kind == Kind::packet && one[0].length == built.size(),
             "a built packet parses as %zu events", one.size());
    return built;
}

} // namespace fz_parser

extern "C" int fz_cpp_parser(const std::uint8_t *data, std::size_t size) {
    using namespace fz_parser;
    if (size == 0) {
        return 0;
    }
    const std::uint8_t control = data[0];
    const std::uint8_t *stream = data + 1;
    const std::size_t n = size - 1;
    static const std::vector<pkg::Device> all = fz::devices();
    const unsigned dev = control >> 6;
    const std::optional<pkg::Device> device =
        dev >= 1 && dev <= all.size() ? std::optional<pkg::Device>(all[dev - 1]) : std::nullopt;
    pkg::SampleTracker tracker;
    const auto whole = events(stream, n, nullptr,
                              [&](bool packet, std::uint64_t offset, const std::uint8_t *b, std::size_t len) {
                                  if (packet) {
                                      check_packet(b, len, offset, device, tracker);
                                  } else {
                                      check_line(b, len, offset, false, device);
                                  }
                              });
    fz::Chunks plan(control);
    const auto chunked =
        events(stream, n, &plan, [](bool, std::uint64_t, const std::uint8_t *, std::size_t) {});
    FZ_CHECK(whole == chunked, "events differ when fed in chunks (%zu / %zu)", whole.size(), chunked.size());
    if (n > 0) {
        const std::vector<std::uint8_t> built =
            wrapped(stream, n, [](bool, std::uint64_t, const std::uint8_t *, std::size_t) {});
        pkg::SampleTracker fresh;
        check_packet(built.data(), built.size(), 0, device, fresh);
    }
    return 0;
}

// Target `decode` (C++): the lean companion of `parser` (see tests/fuzz/c/fuzz_decode.c): one
// whole parse with the event checks, every field decoded with the control byte's device and
// re-encoded, and the stream wrapped into a packet; no chunking, JSON lines or other devices.
// Every packet also goes through the straight-line decoder (decode_packet) and a LayoutCache
// (twice: the second time its shape is known), which must give what decode_field gives.
#ifdef FZ_PACKETS_HEADER
#include FZ_PACKETS_HEADER
#endif
namespace fz_parser {

#ifdef FZ_PACKETS_HEADER
// One decoded field as compared: descriptor and encoded data.
struct Decoded {
    std::uint8_t descriptor = 0;
    std::vector<std::uint8_t> data;
    bool operator==(const Decoded &o) const {
        return descriptor == o.descriptor && data == o.data;
    }
};

template <class T> Decoded decoded_of(const T &value) {
    std::vector<std::uint8_t> buf(pkg::kMaxPayload + 1);
    std::size_t n = 0;
    FZ_CHECK(pkg::encode(value, buf.data(), buf.size(), n) == pkg::EncodeError::none,
             "a decoded %s does not encode", T::kName);
    buf.resize(n);
    return {T::kDescriptor, buf};
}

struct Straight {
    bool has_index = false;
    std::vector<Decoded> fields;
    std::vector<std::size_t> other;
    bool operator==(const Straight &o) const {
        return has_index == o.has_index && fields == o.fields && other == o.other;
    }
};

struct TakeSingleLayout {
    Straight &out;
    bool &taken;
    template <class T> void field(const T &value) {
        if constexpr (!T::kHasVariants) {
            out.fields.push_back(decoded_of(value));
            taken = true;
        }
    }
    void raw(const pkg::DecodeError &) {}
};

template <class Decode>
Straight straight_of(const pkg::PacketView &packet, pkg::AnyPacket &any, Decode &&decode) {
    Straight out;
    const pkg::PacketIndex *index =
        decode(packet, any, [&out](const pkg::FieldEntry &e) { out.other.push_back(e.payload_offset); });
    out.has_index = index != nullptr;
    FZ_CHECK(index == any.index(), "the index is not the set's packet's");
    any.visit([&out](const auto &value) { out.fields.push_back(decoded_of(value)); });
    return out;
}

void check_straight_line(const pkg::PacketView &packet) {
    static pkg::AnyPacket any;
    static pkg::LayoutCache cache;
    cache.clear();
    const Straight straight =
        straight_of(packet, any, [](const pkg::PacketView &p, pkg::AnyPacket &a, auto &&o) {
            return pkg::decode_packet(p, a, o);
        });
    Straight general;
    general.has_index = straight.has_index;
    pkg::FieldIterator it(packet);
    pkg::FieldEntry e;
    bool seen[256] = {};
    while (it.next(e)) {
        bool taken = false;
        if (general.has_index && e.kind == pkg::FieldEntry::Kind::field && !seen[e.descriptor]) {
            pkg::decode_field(packet.set(), e.descriptor, e.data, e.size, std::nullopt,
                              TakeSingleLayout{general, taken});
        }
        if (taken) {
            seen[e.descriptor] = true;
        } else {
            general.other.push_back(e.payload_offset);
        }
    }
    FZ_CHECK(straight == general, "set %u: the straight-line decoder differs from decode_field",
             packet.set());
    for (int round = 0; round < 2; ++round) {
        const Straight cached =
            straight_of(packet, any, [](const pkg::PacketView &p, pkg::AnyPacket &a, auto &&o) {
                return cache.decode(p, a, o);
            });
        FZ_CHECK(cached == general, "set %u: the layout cache (round %d) differs from decode_field",
                 packet.set(), round);
    }
}
#endif

void decode_fields(const std::uint8_t *bytes, std::size_t len, const std::optional<pkg::Device> &device) {
    const pkg::PacketView packet{bytes, len};
    const std::size_t plen = packet.payload_size();
    FZ_CHECK(len == pkg::kHeaderSize + plen + pkg::kChecksumSize, "packet length %zu for payload %zu", len,
             plen);
    const std::uint8_t set = packet.set();
    pkg::FieldIterator it(packet);
    pkg::FieldEntry e;
    std::size_t pos = 0;
    while (it.next(e)) {
        FZ_CHECK(e.payload_offset == pos, "entry at %zu, expected %zu", e.payload_offset, pos);
        if (e.kind == pkg::FieldEntry::Kind::field) {
            pos += pkg::kFieldHeaderSize + e.size;
            FZ_CHECK(pos <= plen, "field runs past the payload");
            FieldCheck check{set, e.descriptor, e.data, e.size};
            pkg::decode_field(set, e.descriptor, e.data, e.size, device, check);
        } else {
            FZ_CHECK(e.size == plen - pos && e.size > 0, "trailing entry does not hold the rest");
            pos = plen;
        }
    }
    FZ_CHECK(pos == plen, "the entries cover %zu of %zu payload bytes", pos, plen);
#ifdef FZ_PACKETS_HEADER
    check_straight_line(packet);
#endif
}

} // namespace fz_parser

extern "C" int fz_cpp_decode(const std::uint8_t *data, std::size_t size) {
    using namespace fz_parser;
    if (size == 0) {
        return 0;
    }
    const std::uint8_t *stream = data + 1;
    const std::size_t n = size - 1;
    static const std::vector<pkg::Device> all = fz::devices();
    const unsigned dev = data[0] >> 6;
    const std::optional<pkg::Device> device =
        dev >= 1 && dev <= all.size() ? std::optional<pkg::Device>(all[dev - 1]) : std::nullopt;
    auto each = [&](bool packet, std::uint64_t, const std::uint8_t *b, std::size_t len) {
        if (packet) {
            decode_fields(b, len, device);
        }
    };
    events(stream, n, nullptr, each);
    if (n > 0) {
        wrapped(stream, n, each);
    }
    return 0;
}
