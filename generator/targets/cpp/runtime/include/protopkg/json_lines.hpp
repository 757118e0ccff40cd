// What the command-line tools do (docs/conformance.md sections 4 and 5): a byte stream to
// canonical JSON lines, and a JSON line back to bytes (lengths and checksums recomputed).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "protopkg/devices.hpp"
#include "protopkg/dispatch.hpp"
#include "protopkg/json_codec.hpp"
#include "protopkg/json_reader.hpp"
#include "protopkg/json_writer.hpp"
#include "protopkg/layouts_json.hpp"
#include "protopkg/lookup.hpp"
#include "protopkg/packet.hpp"
#include "protopkg/parser.hpp"
#include "protopkg/samples.hpp"
#include "protopkg/types_json.hpp"

namespace protopkg {
namespace detail {

struct FieldJsonVisitor {
    JsonWriter &w;
    std::uint8_t descriptor;
    const std::uint8_t *data;
    std::size_t size;

    template <class T> void field(const T &value) {
        if constexpr (T::kHasVariants) {
            head(T::kDescriptor, T::kName, T::kDevice);
        } else {
            head(T::kDescriptor, T::kName, nullptr);
        }
        Json<T>::write(w, value);
        w.end_object();
    }
    /// The members of a decoded field's object before its values (`device`: nullptr for a field
    /// without per-device layouts). Out of line of the per-layout code (compile cost, issue 39).
    PROTOPKG_NOINLINE void head(unsigned id, const char *name, const char *device) {
        w.begin_object();
        w.key("descriptor");
        w.uinteger(id);
        w.key("name");
        w.string(name);
        if (device != nullptr) {
            w.key("device");
            w.string(device);
        }
        w.key("values");
    }
    PROTOPKG_NOINLINE void raw(const DecodeError &err) {
        w.begin_object();
        w.key("descriptor");
        w.uinteger(descriptor);
        w.key("data");
        w.hex(data, size);
        w.key("error");
        w.string(err.text().c_str());
        w.end_object();
    }
};

} // namespace detail

// Compile cost (issue 39): the functions below that reach the field dispatch (decode_field,
// lookup_field over every layout of the package) are templates with a defaulted, unused parameter
// `Defer`, their visitor's type depending on it. A non-template inline function would instantiate
// the whole dispatch and JSON codec in every translation unit that includes this header, called or
// not; as templates they are instantiated only where a program calls them. Callers write the call
// as before (`write_packet_json(w, ...)`, `encode_json_line(line, out, error)`).
namespace detail {
template <class Defer>
using FieldJsonVisitorOf = std::conditional_t<std::is_void_v<Defer>, FieldJsonVisitor, Defer>;
} // namespace detail

/// The canonical object of one payload entry of a packet of set `set`: a decoded field, a raw
/// field or trailing bytes.
template <class Defer = void>
void write_field_entry_json(JsonWriter &w, std::uint8_t set, const FieldEntry &e,
                            const std::optional<Device> &device) {
    if (e.kind == FieldEntry::Kind::trailing) {
        w.begin_object();
        w.key("trailing");
        w.hex(e.data, e.size);
        w.key("error");
        w.string(e.text().c_str());
        w.end_object();
        return;
    }
    detail::FieldJsonVisitorOf<Defer> visitor{w, e.descriptor, e.data, e.size};
    decode_field(set, e.descriptor, e.data, e.size, device, visitor);
}

/// The start of a packet's line, `{"offset":O,"set":S,"fields":[` (the fields and `]}` follow).
inline void write_packet_head(JsonWriter &w, std::uint64_t offset, std::uint8_t set) {
    w.begin_object();
    w.key("offset");
    w.uinteger(offset);
    w.key("set");
    w.uinteger(set);
    w.key("fields");
    w.begin_array();
}

/// {"offset":O,"set":S,"fields":[...]} for one packet (no newline).
template <class Defer = void>
void write_packet_json(JsonWriter &w, std::uint64_t offset, const PacketView &packet,
                       const std::optional<Device> &device) {
    write_packet_head(w, offset, packet.set());
    FieldIterator it(packet);
    FieldEntry e;
    while (it.next(e)) {
        write_field_entry_json<Defer>(w, packet.set(), e, device);
    }
    w.end_array();
    w.end_object();
}

/// {"offset":O,"skipped":"hex"} for one skip run (no newline).
inline void write_skip_json(JsonWriter &w, std::uint64_t offset, const std::uint8_t *bytes,
                            std::size_t count) {
    w.begin_object();
    w.key("offset");
    w.uinteger(offset);
    w.key("skipped");
    w.hex(bytes, count);
    w.end_object();
}

/// {"offset":O,"nmea":"$...*hh"} (the sentence without its CR LF) or {"offset":O,"rtcm":T,"length":L}
/// (message number, payload length) for a foreign frame event (no newline; docs/conformance.md
/// section 5).
inline void write_foreign_json(JsonWriter &w, const StreamEvent &e) {
    w.begin_object();
    w.key("offset");
    w.uinteger(e.offset);
    if (e.kind == StreamEvent::Kind::rtcm) {
        w.key("rtcm");
        w.uinteger(e.rtcm_type());
        w.key("length");
        w.uinteger(e.packet.size - 6);
    } else {
        w.key("nmea");
        w.string(reinterpret_cast<const char *>(e.packet.data), e.packet.size - 2);
    }
    w.end_object();
}

/// Canonical JSON lines of a stream fed in chunks of any size (the decode tool): keeps only the
/// input bytes the parser has not decided on (a candidate packet, a pending skip run), so memory
/// does not grow with the stream. on_line(const std::string&) receives each line without its
/// newline. With `samples`, data packets carry their sample number (docs/conformance.md section 6).
class JsonLinesDecoder {
  public:
    explicit JsonLinesDecoder(const std::optional<Device> &device, bool samples = false)
        : device_(device), samples_(samples) {}

    template <class OnLine> void feed(const std::uint8_t *data, std::size_t size, OnLine &&on_line) {
        hist_.insert(hist_.end(), data, data + size);
        parser_.feed(data, size, [&](const StreamEvent &e) { on_event(e, on_line); });
        trim();
    }

    /// End of input: the remaining lines.
    template <class OnLine> void finish(OnLine &&on_line) {
        parser_.flush([&](const StreamEvent &e) { on_event(e, on_line); });
        trim();
    }

  private:
    template <class OnLine> void on_event(const StreamEvent &e, OnLine &on_line) {
        line_.clear();
        JsonWriter w(string_sink, &line_);
        if (e.kind == StreamEvent::Kind::packet) {
            write_packet_json(w, e.offset, e.packet, device_);
            const std::optional<SamplePlace> place = samples_ ? tracker_.feed(e.packet) : std::nullopt;
            const std::size_t at = line_.find(",\"fields\":");
            if (place && at != std::string::npos) {
                line_.insert(at, ",\"sample\":" + std::to_string(place->number));
            }
        } else if (e.kind == StreamEvent::Kind::skip) {
            write_skip_json(w, e.offset, hist_.data() + (e.offset - hist_base_),
                            static_cast<std::size_t>(e.count));
        } else {
            write_foreign_json(w, e);
        }
        on_line(static_cast<const std::string &>(line_));
    }

    void trim() {
        const std::uint64_t keep = parser_.retain_from();
        const auto drop = static_cast<std::size_t>(keep - hist_base_);
        if (drop > 0) {
            hist_.erase(hist_.begin(), hist_.begin() + static_cast<std::ptrdiff_t>(drop));
            hist_base_ = keep;
        }
    }

    std::optional<Device> device_;
    bool samples_;
    StreamParser parser_;
    SampleTracker tracker_;
    std::vector<std::uint8_t> hist_; ///< input from stream offset hist_base_ on
    std::uint64_t hist_base_ = 0;
    std::string line_;
};

/// Decodes a whole input, fed to a StreamParser `chunk` bytes at a time, into canonical JSON
/// lines; on_line(const std::string&) receives each line without its newline. With `samples`,
/// data packets carry their sample number (docs/conformance.md section 6).
template <class OnLine>
void decode_to_json_lines(const std::uint8_t *input, std::size_t size, std::size_t chunk,
                          const std::optional<Device> &device, OnLine &&on_line, bool samples = false) {
    StreamParser parser;
    SampleTracker tracker;
    std::string line;
    auto on_event = [&](const StreamEvent &e) {
        line.clear();
        JsonWriter w(string_sink, &line);
        if (e.kind == StreamEvent::Kind::packet) {
            write_packet_json(w, e.offset, e.packet, device);
            const std::optional<SamplePlace> place = samples ? tracker.feed(e.packet) : std::nullopt;
            const std::size_t at = line.find(",\"fields\":");
            if (place && at != std::string::npos) {
                line.insert(at, ",\"sample\":" + std::to_string(place->number));
            }
        } else if (e.kind == StreamEvent::Kind::skip) {
            write_skip_json(w, e.offset, input + e.offset, static_cast<std::size_t>(e.count));
        } else {
            write_foreign_json(w, e);
        }
        on_line(static_cast<const std::string &>(line));
    };
    if (chunk == 0) {
        chunk = 1;
    }
    for (std::size_t pos = 0; pos < size; pos += chunk) {
        parser.feed(input + pos, size - pos < chunk ? size - pos : chunk, on_event);
    }
    parser.flush(on_event);
}

namespace detail {

inline bool hex_bytes(const json::Value &x, std::vector<std::uint8_t> &out) {
    if (x.type != json::Value::Type::string || x.text.size() % 2 != 0) {
        return false;
    }
    out.clear();
    std::uint64_t b = 0;
    for (std::size_t i = 0; i < x.text.size(); i += 2) {
        if (!parse_hex_bits(x.text.substr(i, 2), 2, b)) {
            return false;
        }
        out.push_back(static_cast<std::uint8_t>(b));
    }
    return true;
}

inline bool byte_value(const json::Value &x, std::uint8_t &out) {
    JsonError ignored;
    return Json<std::uint8_t>::read(x, out, ignored);
}

/// "offset" of a packet or skip run: required, an integer 0..2^64-1 (its value is not used).
inline bool offset_ok(const json::Value &v, std::string &error) {
    const json::Value *o = v.find("offset");
    bool negative = false;
    std::uint64_t magnitude = 0;
    if (o == nullptr) {
        error = "missing \"offset\"";
        return false;
    }
    if (!json_integer(*o, negative, magnitude) || (negative && magnitude != 0)) {
        error = "offset: expected an integer in 0..18446744073709551615";
        return false;
    }
    return true;
}

/// "error" of a raw field or trailing entry: required, a string (its text is not used).
inline bool error_text_ok(const json::Value &f, JsonError &err) {
    const json::Value *e = f.find("error");
    if (e == nullptr || e->type != json::Value::Type::string) {
        err.path = "error";
        err.message = e == nullptr ? "missing" : "expected a string";
        return false;
    }
    return true;
}

struct EncodeLayouts {
    const json::Value &values;
    const std::string &name;
    const json::Value *device;
    PacketBuilder &builder;
    JsonError &err;
    bool matched = false;
    bool ok = false;

    template <class T, class... Rest> void operator()(Layouts<T, Rest...>) {
        if constexpr (!T::kHasVariants) {
            if (device != nullptr) {
                no_variants(T::kName);
                return;
            }
            matched = true;
            encode_as<T>();
        } else {
            if (device == nullptr || device->type != json::Value::Type::string) {
                name_device(T::kName);
                return;
            }
            attempt<T>();
            (attempt<Rest>(), ...);
            if (!matched) {
                no_layout(T::kName);
            }
        }
    }

    template <class T> void attempt() {
        if (!matched && device->text == T::kDevice) {
            matched = true;
            encode_as<T>();
        }
    }

    template <class T> void encode_as() {
        if (wrong_name(T::kDescriptor, T::kName)) {
            return;
        }
        T value{};
        if (!Json<T>::read(values, value, err)) {
            err.enter("values");
            return;
        }
        if (add_failed(builder.add(value))) {
            return;
        }
        ok = true;
    }

    // The error messages, out of line of the per-layout code (compile cost, issue 39).
    PROTOPKG_NOINLINE void no_variants(const char *field) {
        err.path = "device";
        err.message = std::string("field '") + field + "' has no per-device layouts";
    }
    PROTOPKG_NOINLINE void name_device(const char *field) {
        err.path = "device";
        err.message = std::string("field '") + field + "' has per-device layouts; name the device";
    }
    PROTOPKG_NOINLINE void no_layout(const char *field) {
        err.path = "device";
        err.message = std::string("field '") + field + "' has no layout for device '" +
                      json::printable(device->text) + "'";
    }
    PROTOPKG_NOINLINE bool wrong_name(unsigned id, const char *want) {
        if (name == want) {
            return false;
        }
        err.path = "name";
        err.message =
            "descriptor " + std::to_string(id) + " is '" + want + "', not '" + json::printable(name) + "'";
        return true;
    }
    PROTOPKG_NOINLINE bool add_failed(EncodeError e) {
        if (e == EncodeError::none) {
            return false;
        }
        err.path = "values";
        err.message = to_string(e);
        return true;
    }
};

inline bool fail(JsonError &err, const char *path, const std::string &message) {
    err.path = path;
    err.message = message;
    return false;
}

/// (A template for the compile cost: see write_field_entry_json.)
template <class Defer = void> bool encode_field(const json::Value &f, PacketBuilder &b, JsonError &err) {
    if (f.type != json::Value::Type::object) {
        return fail(err, "", "expected an object");
    }
    std::vector<std::uint8_t> bytes;
    if (const json::Value *t = f.find("trailing")) {
        if (!json_check_object(f, {"trailing", "error"}, err) || !error_text_ok(f, err)) {
            return false;
        }
        if (!hex_bytes(*t, bytes)) {
            return fail(err, "trailing", "expected a string of hex digit pairs");
        }
        if (b.append(bytes.data(), bytes.size()) != EncodeError::none) {
            return fail(err, "trailing", "the payload exceeds " + std::to_string(kMaxPayload) + " bytes");
        }
        return true;
    }
    const json::Value *d = f.find("descriptor");
    std::uint8_t descriptor = 0;
    if (d == nullptr || !byte_value(*d, descriptor)) {
        return fail(err, "descriptor", "expected an integer in 0..255");
    }
    if (const json::Value *data = f.find("data")) {
        if (!json_check_object(f, {"descriptor", "data", "error"}, err) || !error_text_ok(f, err)) {
            return false;
        }
        if (!hex_bytes(*data, bytes)) {
            return fail(err, "data", "expected a string of hex digit pairs");
        }
        const EncodeError e = b.add_raw_field(descriptor, bytes.data(), bytes.size());
        if (e == EncodeError::too_short) {
            return fail(err, "data", to_string(e));
        }
        if (e != EncodeError::none) {
            return fail(err, "data", "the field does not fit in the packet");
        }
        return true;
    }
    const json::Value *values = f.find("values");
    const json::Value *name = f.find("name");
    if (values == nullptr || name == nullptr || name->type != json::Value::Type::string) {
        return fail(
            err, "",
            "expected a decoded field (descriptor, name, values), a raw field (descriptor, data) or a "
            "trailing entry");
    }
    if (!json_check_object(f, {"descriptor", "name", "device", "values"}, err)) {
        return false;
    }
    std::conditional_t<std::is_void_v<Defer>, EncodeLayouts, Defer> enc{*values, name->text, f.find("device"),
                                                                        b, err};
    switch (lookup_field(b.set(), descriptor, enc)) {
    case Lookup::found:
        return enc.ok;
    case Lookup::unknown_set:
        return fail(err, "descriptor",
                    "set " + std::to_string(b.set()) + " is unknown; write the field as raw data");
    case Lookup::unknown_descriptor:
        return fail(err, "descriptor",
                    std::to_string(descriptor) + " is unknown in set " + std::to_string(b.set()) +
                        "; write the field as raw data");
    }
    return false;
}

} // namespace detail

/// Appends the bytes of one JSON line (a packet or a skip run) to `out`; false with `error`
/// (and nothing appended) when the line is not valid.
template <class Defer = void>
bool encode_json_line(const std::string &line, std::vector<std::uint8_t> &out, std::string &error) {
    json::Value v;
    error.clear();
    if (!json::parse(line, v, error)) {
        return false;
    }
    if (v.type != json::Value::Type::object) {
        error = "expected a JSON object";
        return false;
    }
    std::vector<std::uint8_t> bytes;
    if (const json::Value *s = v.find("skipped")) {
        JsonError err;
        if (!json_check_object(v, {"offset", "skipped"}, err)) {
            error = err.text();
            return false;
        }
        if (!detail::offset_ok(v, error)) {
            return false;
        }
        if (!detail::hex_bytes(*s, bytes)) {
            error = "skipped: expected a string of hex digit pairs";
            return false;
        }
        out.insert(out.end(), bytes.begin(), bytes.end());
        return true;
    }
    const json::Value *set = v.find("set");
    const json::Value *fields = v.find("fields");
    if (set == nullptr || fields == nullptr) {
        error = "expected a packet (set, fields) or a skip run (skipped)";
        return false;
    }
    JsonError keys;
    if (!json_check_object(v, {"offset", "set", "fields"}, keys)) {
        error = keys.text();
        return false;
    }
    if (!detail::offset_ok(v, error)) {
        return false;
    }
    std::uint8_t set_id = 0;
    if (!detail::byte_value(*set, set_id)) {
        error = "set: expected an integer in 0..255";
        return false;
    }
    if (fields->type != json::Value::Type::array) {
        error = "fields: expected an array";
        return false;
    }
    PacketBuilder b(set_id);
    for (std::size_t i = 0; i < fields->items.size(); ++i) {
        JsonError err;
        if (!detail::encode_field<Defer>(fields->items[i], b, err)) {
            err.enter_index(i).enter("fields");
            error = err.text();
            return false;
        }
    }
    const PacketView p = b.finish();
    out.insert(out.end(), p.data, p.data + p.size);
    return true;
}

// The default instances (Defer = void) of the functions above are compiled once, into the library
// (src/json_lines.cpp): a program that calls them links them instead of compiling the dispatch
// and the JSON codec of every layout itself.
extern template void write_field_entry_json<void>(JsonWriter &, std::uint8_t, const FieldEntry &,
                                                  const std::optional<Device> &);
extern template void write_packet_json<void>(JsonWriter &, std::uint64_t, const PacketView &,
                                             const std::optional<Device> &);
namespace detail {
extern template bool encode_field<void>(const json::Value &, PacketBuilder &, JsonError &);
} // namespace detail
extern template bool encode_json_line<void>(const std::string &, std::vector<std::uint8_t> &, std::string &);

} // namespace protopkg
