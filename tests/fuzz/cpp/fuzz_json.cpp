// Fuzz target `json` (C++): the input format and the checks of tests/fuzz/c/fuzz_json.c through
// encode_json_line (what the encode tool calls per line): an accepted line's bytes are parsed and
// every event's canonical line must encode back to that event's bytes; a rejected line appends
// nothing and says why. Built as part of fuzz_targets.cpp (entry.cpp picks the target).
#include "fuzz_common.hpp"

namespace fz_json {

namespace pkg = fz::pkg;

void check_line(const std::string &line) {
    std::vector<std::uint8_t> bytes{0xAB};
    std::string error;
    if (!pkg::encode_json_line(line, bytes, error)) {
        FZ_CHECK(bytes.size() == 1 && bytes[0] == 0xAB, "a rejected line appended %zu bytes", bytes.size() - 1);
        FZ_CHECK(!error.empty(), "a rejected line without an error message");
        return;
    }
    bytes.erase(bytes.begin());
    std::uint64_t covered = 0;
    pkg::StreamParser parser;
    std::string text;
    auto on = [&](const pkg::StreamEvent &ev) {
        const bool packet = ev.kind == pkg::StreamEvent::Kind::packet;
        const bool foreign = ev.kind == pkg::StreamEvent::Kind::nmea || ev.kind == pkg::StreamEvent::Kind::rtcm;
        const std::size_t len = static_cast<std::size_t>(packet || foreign ? ev.packet.size : ev.count);
        FZ_CHECK(ev.offset == covered && len <= bytes.size() - covered, "event at %llu, expected %llu",
                 (unsigned long long)ev.offset, (unsigned long long)covered);
        const std::uint8_t *b = bytes.data() + ev.offset;
        covered += len;
        text.clear();
        pkg::JsonWriter w(pkg::string_sink, &text);
        if (foreign) {
            // a foreign frame's line is not encoder input (docs/conformance.md section 5)
            pkg::write_foreign_json(w, ev);
            std::vector<std::uint8_t> refused;
            std::string why;
            FZ_CHECK(!pkg::encode_json_line(text, refused, why) && refused.empty() && !why.empty(),
                     "the foreign frame's line encodes or is refused without a message: %s", text.c_str());
            return;
        }
        if (packet) {
            pkg::write_packet_json(w, ev.offset, pkg::PacketView{b, len}, std::nullopt);
        } else {
            pkg::write_skip_json(w, ev.offset, b, len);
        }
        std::vector<std::uint8_t> again;
        std::string why;
        FZ_CHECK(pkg::encode_json_line(text, again, why), "the decoded line does not encode (%s): %s", why.c_str(),
                 text.c_str());
        FZ_CHECK(again.size() == len && std::memcmp(again.data(), b, len) == 0, "%s encodes to %s, not %s",
                 text.c_str(), fz::hex(again.data(), again.size()).c_str(), fz::hex(b, len).c_str());
    };
    parser.feed(bytes.data(), bytes.size(), on);
    parser.flush(on);
    FZ_CHECK(covered == bytes.size(), "the events cover %llu of %zu bytes", (unsigned long long)covered,
             bytes.size());
}

} // namespace fz_json

extern "C" int fz_cpp_json(const std::uint8_t *data, std::size_t size) {
    using namespace fz_json;
    const char *text = reinterpret_cast<const char *>(data);
    std::size_t start = 0;
    while (start < size) {
        const void *nl = std::memchr(text + start, '\n', size - start);
        const std::size_t n = nl ? static_cast<std::size_t>(static_cast<const char *>(nl) - (text + start)) : size - start;
        check_line(std::string(text + start, n));
        start += n + 1;
    }
    return 0;
}
