// Field dispatch (docs/conformance.md section 2): decode a field by (set, descriptor), trying
// per-device variants in IR order (or only the chosen device's), with a raw fallback.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "protopkg/devices.hpp"
#include "protopkg/lookup.hpp"
#include "protopkg/wire.hpp"

namespace protopkg {
namespace detail {

template <class Visitor> struct DecodeLayouts {
    const std::uint8_t *data;
    std::size_t size;
    const std::optional<Device> &device;
    Visitor &visitor;

    template <class T, class... Rest> void operator()(Layouts<T, Rest...>) const {
        if constexpr (!T::kHasVariants) {
            if constexpr (Plain<T>::kPlain) {
                if (size == Plain<T>::kSize) {
                    T value;
                    Plain<T>::load(data, value);
                    visitor.field(static_cast<const T &>(value));
                    return;
                }
            }
            checked<T>();
        } else {
            variants<T, Rest...>();
        }
    }

    // Fields with per-device layouts: only the chosen device's layout when the field has one
    // for it, else all in order; the first that decodes wins, else the first error.
    template <class T, class... Rest> PROTOPKG_NOINLINE void variants() const {
        const bool chosen =
            device.has_value() && ((T::kDeviceId == *device) || ... || (Rest::kDeviceId == *device));
        DecodeError first;
        bool have_first = false;
        bool done = false;
        attempt<T>(chosen, first, have_first, done);
        (attempt<Rest>(chosen, first, have_first, done), ...);
        if (!done) {
            visitor.raw(static_cast<const DecodeError &>(first));
        }
    }

    // The checked decode of a single-layout field (and its error), out of the straight path.
    template <class T> PROTOPKG_NOINLINE void checked() const {
        T value{};
        DecodeError err;
        if (decode(data, size, value, err)) {
            visitor.field(static_cast<const T &>(value));
        } else {
            visitor.raw(static_cast<const DecodeError &>(err));
        }
    }

    template <class T> void attempt(bool chosen, DecodeError &first, bool &have_first, bool &done) const {
        if (done || (chosen && T::kDeviceId != *device)) {
            return;
        }
        if constexpr (Plain<T>::kPlain) {
            if (size == Plain<T>::kSize) {
                T value;
                Plain<T>::load(data, value);
                visitor.field(static_cast<const T &>(value));
                done = true;
                return;
            }
        }
        T value{};
        DecodeError err;
        if (decode(data, size, value, err)) {
            visitor.field(static_cast<const T &>(value));
            done = true;
        } else if (!have_first) {
            first = err;
            have_first = true;
        }
    }
};

} // namespace detail

/// Decodes the data of field (set, descriptor). Calls visitor.field(const T&) with the decoded
/// layout struct (T::kName, T::kDevice tell which), or visitor.raw(const DecodeError&) when the
/// field cannot be decoded (unknown set or descriptor, or the layout's decode error).
/// Inlined into the caller's field loop: two table loads and the one indirect call of
/// visit_case per field, no call in front of it.
template <class Visitor>
PROTOPKG_INLINE void decode_field(std::uint8_t set, std::uint8_t descriptor, const std::uint8_t *data,
                                  std::size_t size, const std::optional<Device> &device, Visitor &&visitor) {
    detail::DecodeLayouts<std::remove_reference_t<Visitor>> d{data, size, device, visitor};
    switch (lookup_field(set, descriptor, d)) {
    case Lookup::found:
        return;
    case Lookup::unknown_set:
        visitor.raw(DecodeError::of(DecodeError::Kind::unknown_set));
        return;
    case Lookup::unknown_descriptor:
        visitor.raw(DecodeError::of(DecodeError::Kind::unknown_descriptor));
        return;
    }
}

/// Whether the data of field (set, descriptor) decodes (with the device's layout when chosen): false
/// with the error decode_field would give visitor.raw. One instance of the dispatch, compiled into
/// the library (src/dispatch.cpp), for callers that need no value (the session's reply check).
bool decodes_field(std::uint8_t set, std::uint8_t descriptor, const std::uint8_t *data, std::size_t size,
                   const std::optional<Device> &device, DecodeError &err);

} // namespace protopkg
