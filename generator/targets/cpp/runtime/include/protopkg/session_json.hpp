// The session tool's lines (docs/conformance.md section 8): a command's result line, and the
// canonical lines of the packets and skip runs a session reports.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "protopkg/json_lines.hpp"
#include "protopkg/session.hpp"

namespace protopkg {

/// {"line":N,"result":"ack","code":C,"reply":[...]} (with "error" for invalid and refused).
inline void write_result_json(JsonWriter &w, std::uint64_t line, const Result &r,
                              const std::optional<Device> &device) {
    w.begin_object();
    w.key("line");
    w.uinteger(line);
    w.key("result");
    w.string(to_string(r.status));
    w.key("code");
    if (r.has_code) {
        if (r.code < 0) {
            w.integer(r.code);
        } else {
            w.uinteger(static_cast<std::uint64_t>(r.code));
        }
    } else {
        w.null();
    }
    w.key("reply");
    w.begin_array();
    const PacketView packet = r.reply_packet();
    r.for_each_reply([&](const FieldEntry &e) { write_field_entry_json(w, packet.set(), e, device); });
    w.end_array();
    if (r.has_error) {
        w.key("error");
        w.string(r.error.c_str());
    }
    w.end_object();
}

/// The line of one session event (no newline); `bytes` gives the stream bytes of a skip run
/// (stream offset -> pointer), as kept by the caller from Session::retain_from() on.
template <class Bytes>
std::string session_event_line(const SessionEvent &e, const std::optional<Device> &device, Bytes &&bytes) {
    std::string line;
    JsonWriter w(string_sink, &line);
    switch (e.kind) {
    case SessionEvent::Kind::result:
        write_result_json(w, e.result->tag, *e.result, device);
        break;
    case SessionEvent::Kind::packet:
        write_packet_json(w, e.offset, e.packet, device);
        break;
    case SessionEvent::Kind::skip:
        write_skip_json(w, e.offset, bytes(e.offset), static_cast<std::size_t>(e.count));
        break;
    case SessionEvent::Kind::nmea:
    case SessionEvent::Kind::rtcm: {
        StreamEvent f;
        f.kind = e.kind == SessionEvent::Kind::nmea ? StreamEvent::Kind::nmea : StreamEvent::Kind::rtcm;
        f.offset = e.offset;
        f.packet = e.packet;
        write_foreign_json(w, f);
        break;
    }
    }
    return line;
}

namespace detail {

template <class F> struct CommandPick {
    const json::Value &values;
    const json::Value *device;
    F &f;
    std::string &error;
    const std::string &name;
    std::uint8_t set;
    std::uint8_t descriptor;
    bool done = false;

    template <class T, class... Rest> void operator()(Layouts<T, Rest...>) {
        attempt<T>();
        (attempt<Rest>(), ...);
        if (!done && error.empty()) {
            not_command();
        }
    }

    template <class T> void attempt() {
        if (done || !error.empty()) {
            return;
        }
        if constexpr (T::kHasVariants) {
            if (device == nullptr || device->type != json::Value::Type::string ||
                device->text != T::kDevice) {
                return;
            }
        }
        if constexpr (CommandTraits<T>::kCommand) {
            T value{};
            JsonError err;
            if (!Json<T>::read(values, value, err)) {
                err.enter("values");
                error = err.text();
                return;
            }
            done = true;
            f(static_cast<const T &>(value));
        } else {
            not_command();
        }
    }

    void not_command() {
        error = json::printable(name) + " (set " + std::to_string(set) + ", descriptor " +
                std::to_string(descriptor) + ") is not a command";
    }
};

} // namespace detail

/// The command of one input line of the session tool (a packet line as the encoder accepts it,
/// with exactly one decoded command field): calls f(const T&) with the command's layout value, or
/// returns false with `error` naming the problem.
template <class F> bool with_command_from_line(const std::string &line, std::string &error, F &&f) {
    std::vector<std::uint8_t> bytes;
    error.clear();
    if (!encode_json_line(line, bytes, error)) {
        return false;
    }
    json::Value v;
    if (!json::parse(line, v, error)) {
        return false;
    }
    const json::Value *fields = v.find("fields");
    if (fields == nullptr) {
        error = "expected a packet line with one command field, not a skip run";
        return false;
    }
    if (fields->items.size() != 1) {
        error = "expected exactly one command field, got " + std::to_string(fields->items.size());
        return false;
    }
    const json::Value &field = fields->items[0];
    const json::Value *values = field.find("values");
    const json::Value *name = field.find("name");
    std::uint8_t set = 0;
    std::uint8_t descriptor = 0;
    if (values == nullptr || name == nullptr || !detail::byte_value(*v.find("set"), set) ||
        !detail::byte_value(*field.find("descriptor"), descriptor)) {
        error = "expected a decoded command field (descriptor, name, values), not a raw field";
        return false;
    }
    detail::CommandPick<F> pick{*values, field.find("device"), f, error, name->text, set, descriptor};
    if (lookup_field(set, descriptor, pick) != Lookup::found || !pick.done) {
        if (error.empty()) {
            pick.not_command();
        }
        return false;
    }
    return true;
}

} // namespace protopkg
