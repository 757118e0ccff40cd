// Packets: building them (header, fields, checksum) and splitting a payload into fields.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <type_traits>

#include "protopkg/checksum.hpp"
#include "protopkg/framing.hpp"
#include "protopkg/wire.hpp"

namespace protopkg {

/// A complete packet (sync .. checksum) as found by StreamParser or made by PacketBuilder, or
/// any bytes a user points it at: every accessor stays within `size` bytes of `data`, whatever
/// the length byte says (a truncated buffer gives a shorter payload, never a read past it).
/// `valid()` tells whether the bytes are one whole packet: header, payload and checksum as long
/// as the length byte says.
struct PacketView {
    const std::uint8_t *data = nullptr;
    std::size_t size = 0;

    /// The descriptor set, or 0 when the view is too short to hold the header.
    std::uint8_t set() const {
        return data != nullptr && size >= kHeaderSize ? data[kSetOffset] : 0;
    }
    /// The payload's first byte (meaningful for payload_size() bytes).
    const std::uint8_t *payload() const {
        return data != nullptr && size >= kHeaderSize ? data + kHeaderSize : data;
    }
    /// The payload's size: the length byte, cut to the bytes the view holds after the header.
    std::size_t payload_size() const {
        if (data == nullptr || size < kHeaderSize) {
            return 0;
        }
        const std::size_t stated = data[kLengthOffset];
        const std::size_t held = size - kHeaderSize;
        return stated < held ? stated : held;
    }
    /// True when the view holds exactly one packet: header, the payload its length byte states,
    /// and the checksum (not verified here; see StreamParser).
    bool valid() const {
        return data != nullptr && size >= kHeaderSize + kChecksumSize &&
               size == kHeaderSize + std::size_t{data[kLengthOffset]} + kChecksumSize;
    }
};

namespace detail {
template <class T, class = void> struct HasSet : std::false_type {};
template <class T> struct HasSet<T, std::void_t<decltype(T::kSet)>> : std::true_type {};
} // namespace detail

/// Appends fields to a bounded buffer and finalises length and checksum. No heap.
class PacketBuilder {
  public:
    explicit PacketBuilder(std::uint8_t set) : set_(set) {}

    std::uint8_t set() const {
        return set_;
    }
    std::size_t payload_size() const {
        return payload_size_;
    }
    /// First error met while adding (later additions are ignored).
    EncodeError error() const {
        return error_;
    }

    /// Appends a field from its descriptor and data (the header is written here).
    EncodeError add_raw_field(std::uint8_t descriptor, const std::uint8_t *data, std::size_t size) {
        std::uint8_t *f = begin_field();
        if (f == nullptr) {
            return error_;
        }
        const std::size_t cap = field_capacity();
        if (size > cap) {
            return fail(EncodeError::overflow);
        }
        if (size > 0) {
            std::memcpy(f + kFieldHeaderSize, data, size);
        }
        return end_field(descriptor, size);
    }

    /// Appends a typed field (any generated layout struct: uses T::kDescriptor). A layout of
    /// another descriptor set than the builder's (T::kSet) is refused with EncodeError::wrong_set:
    /// its descriptor means another field there. Shared data fields (sample_rule::is_shared) go
    /// in any set; reserved fields (ack/nack, no kSet) in any set of their kind.
    template <class T> EncodeError add(const T &value) {
        if constexpr (detail::HasSet<T>::value) {
            if (T::kSet != set_ && !sample_rule::is_shared(T::kDescriptor) && error_ == EncodeError::none) {
                return fail(EncodeError::wrong_set);
            }
        }
        std::uint8_t *f = begin_field();
        if (f == nullptr) {
            return error_;
        }
        Writer w(f + kFieldHeaderSize, field_capacity());
        Codec<T>::write(w, value);
        if (w.error() != EncodeError::none) {
            return fail(w.error());
        }
        return end_field(T::kDescriptor, w.size());
    }

    /// Appends raw payload bytes (a trailing entry that is not a whole field).
    EncodeError append(const std::uint8_t *data, std::size_t size) {
        if (error_ != EncodeError::none) {
            return error_;
        }
        if (size > kMaxPayload - payload_size_) {
            return fail(EncodeError::overflow);
        }
        if (size > 0) {
            std::memcpy(buf_.data() + kHeaderSize + payload_size_, data, size);
        }
        payload_size_ += size;
        return EncodeError::none;
    }

    /// Writes sync, header and checksum; the view stays valid while the builder lives.
    PacketView finish() {
        for (std::size_t i = 0; i < kSyncSize; ++i) {
            buf_[i] = kSync[i];
        }
        buf_[kSetOffset] = set_;
        buf_[kLengthOffset] = static_cast<std::uint8_t>(payload_size_);
        const std::size_t body = kHeaderSize + payload_size_;
        const auto sums = fletcher16(buf_.data(), body).bytes();
        buf_[body] = sums[0];
        buf_[body + 1] = sums[1];
        return PacketView{buf_.data(), body + kChecksumSize};
    }

  private:
    std::uint8_t *begin_field() {
        if (error_ != EncodeError::none) {
            return nullptr;
        }
        if (kMaxPayload - payload_size_ < kFieldHeaderSize) {
            fail(EncodeError::overflow);
            return nullptr;
        }
        return buf_.data() + kHeaderSize + payload_size_;
    }
    std::size_t field_capacity() const {
        const std::size_t room = kMaxPayload - payload_size_ - kFieldHeaderSize;
        return room < kMaxFieldData ? room : kMaxFieldData;
    }
    EncodeError end_field(std::uint8_t descriptor, std::size_t data_size) {
        const int length = static_cast<int>(data_size) + field_length_adjust(set_, descriptor);
        if (length < 0) {
            return fail(EncodeError::too_short);
        }
        if (length > 0xFF) {
            return fail(EncodeError::overflow);
        }
        std::uint8_t *f = buf_.data() + kHeaderSize + payload_size_;
        f[kFieldLengthOffset] = static_cast<std::uint8_t>(length);
        f[kFieldDescriptorOffset] = descriptor;
        payload_size_ += kFieldHeaderSize + data_size;
        return EncodeError::none;
    }
    EncodeError fail(EncodeError e) {
        if (error_ == EncodeError::none) {
            error_ = e;
        }
        return e;
    }

    std::array<std::uint8_t, kMaxPacket> buf_{};
    std::uint8_t set_;
    std::size_t payload_size_ = 0;
    EncodeError error_ = EncodeError::none;
};

/// One entry of a payload: a complete field, or trailing bytes that do not form one.
struct FieldEntry {
    enum class Kind : std::uint8_t { field, trailing };
    /// Why the rest of the payload is trailing (docs/conformance.md section 2).
    enum class Problem : std::uint8_t { none, short_header, length_below_header, overruns };

    Kind kind = Kind::field;
    std::uint8_t descriptor = 0;
    const std::uint8_t *data = nullptr; ///< field data (after the header), or the trailing bytes
    std::size_t size = 0;
    std::size_t payload_offset = 0; ///< where the field (header) or trailing bytes start
    Problem problem = Problem::none;
    std::uint8_t length = 0; ///< the length byte as sent (trailing entries)
    std::size_t left = 0;    ///< bytes left from payload_offset (trailing entries)

    /// The exact message of a trailing entry.
    ErrorText text() const {
        ErrorText t;
        using ull = unsigned long long;
        switch (problem) {
        case Problem::none:
            std::snprintf(t.text.data(), t.text.size(), "no error");
            break;
        case Problem::short_header:
            std::snprintf(t.text.data(), t.text.size(),
                          "field header at payload offset %llu needs %llu bytes, %llu left",
                          ull(payload_offset), ull(kFieldHeaderSize), ull(left));
            break;
        case Problem::length_below_header:
            std::snprintf(t.text.data(), t.text.size(),
                          "field length %u at payload offset %llu is shorter than the field header",
                          unsigned(length), ull(payload_offset));
            break;
        case Problem::overruns:
            std::snprintf(t.text.data(), t.text.size(),
                          "field length %u at payload offset %llu overruns the payload (%llu bytes left)",
                          unsigned(length), ull(payload_offset), ull(left));
            break;
        }
        return t;
    }
};

/// Splits a payload into fields; a framing problem ends the walk with one trailing entry.
class FieldIterator {
  public:
    /// The payload of a packet of descriptor set `set` (the set decides irregular field lengths).
    FieldIterator(std::uint8_t set, const std::uint8_t *payload, std::size_t size)
        : set_(set), p_(payload), size_(size) {}
    explicit FieldIterator(const PacketView &packet)
        : FieldIterator(packet.set(), packet.payload(), packet.payload_size()) {}

    /// Fills `out` with the next entry; false at the end of the payload.
    bool next(FieldEntry &out) {
        if (pos_ >= size_) {
            return false;
        }
        const std::size_t left = size_ - pos_;
        if (left >= kFieldHeaderSize) {
            // The common case, a whole field: only the members a field uses are written.
            const std::uint8_t length = p_[pos_ + kFieldLengthOffset];
            const std::uint8_t descriptor = p_[pos_ + kFieldDescriptorOffset];
            const int data_length = static_cast<int>(length) - field_length_adjust(set_, descriptor);
            if (data_length >= 0 && kFieldHeaderSize + static_cast<std::size_t>(data_length) <= left) {
                out.kind = FieldEntry::Kind::field;
                out.descriptor = descriptor;
                out.data = p_ + pos_ + kFieldHeaderSize;
                out.size = static_cast<std::size_t>(data_length);
                out.payload_offset = pos_;
                out.problem = FieldEntry::Problem::none;
                out.length = 0;
                out.left = 0;
                pos_ += kFieldHeaderSize + static_cast<std::size_t>(data_length);
                return true;
            }
        }
        // A framing problem: the rest of the payload is one trailing entry.
        out = FieldEntry{};
        out.payload_offset = pos_;
        if (left < kFieldHeaderSize) {
            return trailing(out, FieldEntry::Problem::short_header, 0, left);
        }
        const std::uint8_t length = p_[pos_ + kFieldLengthOffset];
        const std::uint8_t descriptor = p_[pos_ + kFieldDescriptorOffset];
        if (static_cast<int>(length) - field_length_adjust(set_, descriptor) < 0) {
            return trailing(out, FieldEntry::Problem::length_below_header, length, left);
        }
        return trailing(out, FieldEntry::Problem::overruns, length, left);
    }

  private:
    bool trailing(FieldEntry &out, FieldEntry::Problem problem, std::uint8_t length, std::size_t left) {
        out.kind = FieldEntry::Kind::trailing;
        out.problem = problem;
        out.length = length;
        out.left = left;
        out.data = p_ + pos_;
        out.size = left;
        pos_ = size_;
        return true;
    }

    std::uint8_t set_;
    const std::uint8_t *p_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

} // namespace protopkg
