// Helpers shared by the tests: hex, whole-stream decode to JSON text, JSON text to bytes.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "codec/dispatch.h"
#include "codec/json.h"
#include "codec/parser.h"

namespace test_support {

inline std::vector<uint8_t> from_hex(const std::string &hex) {
    std::vector<uint8_t> out;
    for (size_t i = 0; i + 1 < hex.size(); i += 2) {
        out.push_back(static_cast<uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
    }
    return out;
}

inline std::string to_hex(const std::vector<uint8_t> &bytes) {
    static const char digits[] = "0123456789abcdef";
    std::string out;
    for (uint8_t b : bytes) {
        out += digits[b >> 4];
        out += digits[b & 0x0F];
    }
    return out;
}

struct Event {
    codec_event_kind_t kind;
    uint64_t offset;
    uint64_t length;
    bool operator==(const Event &o) const {
        return kind == o.kind && offset == o.offset && length == o.length;
    }
};

struct Collector {
    const std::vector<uint8_t> *input = nullptr;
    codec_device_t device = CODEC_DEVICE_ANY;
    std::string text;
    std::vector<Event> events;
};

inline void collect(void *arg, const codec_event_t *ev) {
    Collector *c = static_cast<Collector *>(arg);
    c->events.push_back(Event{ev->kind, ev->offset, ev->length});
    std::string line(1024, '\0');
    size_t n;
    for (;;) {
        if (ev->kind == CODEC_EVENT_SKIP) {
            n = codec_json_skip_line(ev->offset, c->input->data() + ev->offset,
                                     static_cast<size_t>(ev->length), &line[0], line.size());
        } else {
            n = codec_json_packet_line(ev->packet, static_cast<size_t>(ev->length), ev->offset, c->device,
                                       &line[0], line.size());
        }
        if (n < line.size()) {
            break;
        }
        line.assign(n + 1, '\0');
    }
    c->text.append(line.data(), n);
    c->text += '\n';
}

// Feeds the bytes in chunks of `chunk` bytes (0: all at once); returns the JSON lines.
inline Collector decode(const std::vector<uint8_t> &bytes, size_t chunk,
                        codec_device_t device = CODEC_DEVICE_ANY) {
    Collector c;
    c.input = &bytes;
    c.device = device;
    codec_parser_t parser;
    codec_parser_init(&parser);
    if (chunk == 0) {
        codec_parser_feed(&parser, bytes.data(), bytes.size(), collect, &c);
    } else {
        for (size_t i = 0; i < bytes.size(); i += chunk) {
            size_t n = bytes.size() - i < chunk ? bytes.size() - i : chunk;
            codec_parser_feed(&parser, bytes.data() + i, n, collect, &c);
        }
    }
    codec_parser_flush(&parser, collect, &c);
    return c;
}

inline std::string decode_text(const std::vector<uint8_t> &bytes, size_t chunk,
                               codec_device_t device = CODEC_DEVICE_ANY) {
    return decode(bytes, chunk, device).text;
}

struct StraightLine {
    std::vector<size_t> other; // payload offsets of the entries left to the general path
};

inline void note_other(void *arg, const codec_field_entry_t *entry) {
    static_cast<StraightLine *>(arg)->other.push_back(entry->offset);
}

inline std::vector<uint8_t> encoded(const codec_field_value_t &value) {
    std::vector<uint8_t> out(CODEC_MAX_PAYLOAD + 1);
    size_t n = 0;
    if (codec_encode_field(&value, out.data(), out.size(), &n) != CODEC_OK) {
        return {};
    }
    out.resize(n);
    return out;
}

// The encoding of the i-th member a packet index holds (the member copied into a general value of
// the field's only layout, as far as the packet struct `whole` goes); empty if it does not encode.
inline std::vector<uint8_t> member_encoding(uint8_t set, const codec_packet_index_t *index, size_t i,
                                            const codec_packet_t &whole) {
    const codec_field_info_t *info = codec_find_field(set, index->fields[i].descriptor, nullptr);
    if (info == nullptr || info->layout_count != 1) {
        return {};
    }
    static codec_field_value_t value;
    const uint8_t *member = static_cast<const uint8_t *>(codec_packet_value(index, i));
    const size_t room = static_cast<size_t>(reinterpret_cast<const uint8_t *>(&whole + 1) - member);
    std::memset(&value, 0, sizeof value);
    value.id = info->first_layout;
    std::memcpy(&value.u, member, room < sizeof value.u ? room : sizeof value.u);
    return encoded(value);
}

// The layout cache (codec_decode_packet_cached, issue 38) against the straight-line decoder on one
// packet (its index and other entries given), twice through the same cache (the second time by
// the packet's shape, when its first decode recorded one, which every packet decoded whole into
// 1..CODEC_LAYOUT_SHAPE_FIELDS members must have): the same index, members that encode to the
// same bytes, the same other entries. Returns "" when they agree, else what differs.
inline std::string cached_mismatch(codec_layout_cache_t *cache, const std::vector<uint8_t> &pk,
                                   const codec_packet_index_t *index, const codec_packet_t &decoded,
                                   const StraightLine &sl) {
    static codec_packet_t via;
    const uint8_t set = codec_packet_set(pk.data());
    for (int pass = 0; pass < 2; pass++) {
        StraightLine cl;
        const codec_packet_index_t *ci = codec_decode_packet_cached(cache, pk.data(), &via, note_other, &cl);
        const std::string when = pass == 0 ? "first decode: " : "second decode: ";
        if ((ci == nullptr) != (index == nullptr)) {
            return when + "an index where the straight-line decoder has none, or none where it has one";
        }
        if (cl.other != sl.other) {
            return when + "other entries differ";
        }
        if (index == nullptr) {
            continue;
        }
        if (via.set != decoded.set || ci->count != index->count ||
            std::memcmp(ci->present, index->present, sizeof ci->present) != 0) {
            return when + "another index (set, count or present bits)";
        }
        for (size_t i = 0; i < index->count; i++) {
            if (ci->fields[i].descriptor != index->fields[i].descriptor ||
                ci->fields[i].offset != index->fields[i].offset) {
                return when + "index entry " + std::to_string(i) + " differs";
            }
            const std::vector<uint8_t> want = member_encoding(set, index, i, decoded);
            if (want.empty() || member_encoding(set, ci, i, via) != want) {
                return when + "descriptor " + std::to_string(index->fields[i].descriptor) + ": another value";
            }
        }
        const bool whole = sl.other.empty() && index->count >= 1 && index->count <= CODEC_LAYOUT_SHAPE_FIELDS;
        if (pass == 0 && whole &&
            codec_layout_cache_find_(cache, set, codec_packet_payload(pk.data()),
                                     codec_packet_payload_length(pk.data())) == nullptr) {
            return "a packet decoded whole into its members has no cached shape";
        }
    }
    return "";
}

// The straight-line decoder (codec_decode_packet, issue 38) against the general dispatch on
// every packet of a stream: each field the general path decodes with a field's only layout (the
// first time its descriptor occurs in the packet) is decoded, in packet order, to a value that
// encodes to the same bytes; every other entry goes to the callback, in order. Returns "" when
// they agree, else what differs.
inline std::string straight_line_mismatch(const std::vector<uint8_t> &bytes) {
    struct Packets {
        std::vector<std::vector<uint8_t>> list;
    } packets;
    codec_parser_t parser;
    codec_parser_init(&parser);
    auto keep = [](void *arg, const codec_event_t *ev) {
        if (ev->kind == CODEC_EVENT_PACKET) {
            static_cast<Packets *>(arg)->list.emplace_back(ev->packet, ev->packet + ev->length);
        }
    };
    codec_parser_feed(&parser, bytes.data(), bytes.size(), keep, &packets);
    codec_parser_flush(&parser, keep, &packets);
    static codec_packet_t decoded;
    static codec_layout_cache_t cache; // one per stream, as a program has
    codec_layout_cache_init(&cache);
    for (const std::vector<uint8_t> &pk : packets.list) {
        const uint8_t set = codec_packet_set(pk.data());
        StraightLine sl;
        const codec_packet_index_t *index = codec_decode_packet(pk.data(), &decoded, note_other, &sl);
        codec_field_iter_t it;
        codec_field_entry_t e;
        std::vector<size_t> other;
        size_t next = 0;
        bool seen[256] = {};
        codec_field_iter_init(&it, set, codec_packet_payload(pk.data()),
                              codec_packet_payload_length(pk.data()));
        while (codec_field_iter_next(&it, &e)) {
            codec_field_value_t general;
            codec_field_value_t straight;
            const codec_field_info_t *info = codec_find_field(set, e.descriptor, nullptr);
            const bool plain = index != nullptr && e.kind == CODEC_ENTRY_FIELD && info != nullptr &&
                               info->layout_count == 1 && !seen[e.descriptor] &&
                               codec_decode_field(set, e.descriptor, e.data, e.length, CODEC_DEVICE_ANY,
                                                  &general, nullptr) == CODEC_OK;
            if (!plain) {
                other.push_back(e.offset);
                continue;
            }
            seen[e.descriptor] = true;
            if (next >= index->count || index->fields[next].descriptor != e.descriptor) {
                return "set " + std::to_string(set) + " descriptor " + std::to_string(e.descriptor) +
                       ": not the next field decoded";
            }
            // the member, copied into a general value of the same layout (as far as the packet
            // struct goes: the member lies inside it)
            const uint8_t *member = static_cast<const uint8_t *>(codec_packet_value(index, next));
            const size_t room = static_cast<size_t>(reinterpret_cast<const uint8_t *>(&decoded + 1) - member);
            straight.id = general.id;
            std::memcpy(&straight.u, member, room < sizeof straight.u ? room : sizeof straight.u);
            if (encoded(straight) != encoded(general) || encoded(general).empty()) {
                return "set " + std::to_string(set) + " descriptor " + std::to_string(e.descriptor) +
                       ": another value than the general dispatch";
            }
            next++;
        }
        if (index != nullptr && next != index->count) {
            return "set " + std::to_string(set) + ": more fields decoded than the general dispatch";
        }
        if (other != sl.other) {
            return "set " + std::to_string(set) + ": other entries differ";
        }
        const std::string cached = cached_mismatch(&cache, pk, index, decoded, sl);
        if (!cached.empty()) {
            return "set " + std::to_string(set) + ": layout cache: " + cached;
        }
        // The same shape with other data (every data byte 0xFF: a bool, enum or count that no
        // longer decodes): the cache, which now holds the shape, must give what the straight-line
        // decoder gives.
        std::vector<uint8_t> mutant = pk;
        codec_field_iter_init(&it, set, codec_packet_payload(pk.data()),
                              codec_packet_payload_length(pk.data()));
        while (codec_field_iter_next(&it, &e)) {
            if (e.kind == CODEC_ENTRY_FIELD && e.length > 0) {
                std::memset(&mutant[static_cast<size_t>(e.data - pk.data())], 0xFF, e.length);
            }
        }
        StraightLine ms;
        const codec_packet_index_t *mi = codec_decode_packet(mutant.data(), &decoded, note_other, &ms);
        const std::string other_data = cached_mismatch(&cache, mutant, mi, decoded, ms);
        if (!other_data.empty()) {
            return "set " + std::to_string(set) + ": layout cache, the shape with other data: " + other_data;
        }
    }
    return "";
}

// Encodes newline-separated JSON lines; false and a message on the first bad line.
inline bool encode_text(const std::string &text, std::vector<uint8_t> *out, std::string *error) {
    size_t start = 0;
    while (start < text.size()) {
        size_t nl = text.find('\n', start);
        if (nl == std::string::npos) {
            nl = text.size();
        }
        std::string line = text.substr(start, nl - start);
        start = nl + 1;
        if (line.empty()) {
            continue;
        }
        std::vector<uint8_t> buf(line.size() / 2 + CODEC_MAX_PACKET);
        char msg[512];
        size_t n = 0;
        codec_status_t st =
            codec_json_encode_line(line.data(), line.size(), buf.data(), buf.size(), &n, msg, sizeof msg);
        if (st != CODEC_OK) {
            *error = msg;
            return false;
        }
        out->insert(out->end(), buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(n));
    }
    return true;
}

// A packet of descriptor set `set` holding the given (descriptor, data) fields.
inline std::vector<uint8_t> packet(uint8_t set,
                                   const std::vector<std::pair<uint8_t, std::vector<uint8_t>>> &fields) {
    std::vector<uint8_t> buf(CODEC_MAX_PACKET);
    codec_packet_builder_t b;
    codec_packet_begin(&b, buf.data(), buf.size(), set);
    for (const auto &f : fields) {
        codec_packet_add_field(&b, f.first, f.second.data(), f.second.size());
    }
    size_t n = 0;
    if (codec_packet_finish(&b, &n) != CODEC_OK) {
        return {};
    }
    buf.resize(n);
    return buf;
}

// A byte that is not part of the sync sequence (garbage that cannot start a packet).
inline uint8_t garbage_byte() {
    for (unsigned b = 0;; b++) {
        bool in_sync = false;
        for (size_t i = 0; i < CODEC_SYNC_SIZE; i++) {
            in_sync = in_sync || codec_sync[i] == b;
        }
        if (!in_sync) {
            return static_cast<uint8_t>(b);
        }
    }
}

} // namespace test_support
