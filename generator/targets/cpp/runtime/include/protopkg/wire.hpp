// Wire primitives: bounded containers, decode errors, Reader/Writer and Codec<T> for primitives.
// Decoding and encoding never allocate and never read or write out of bounds.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>

#include "protopkg/framing.hpp"

/// Keeps a function out of line (the checked and error paths of decode_field), so that the
/// straight path it is called from needs no stack frame.
#if defined(__GNUC__) || defined(__clang__)
#define PROTOPKG_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define PROTOPKG_NOINLINE __declspec(noinline)
#else
#define PROTOPKG_NOINLINE
#endif
/// Inlines the straight loads of plain layouts (Plain<V>::load) into their caller: they are a
/// few loads and byte swaps, but a big caller (the switch of visit_case) would not inline them.
#if !defined(PROTOPKG_INLINE)
#if defined(__GNUC__) || defined(__clang__)
#define PROTOPKG_INLINE inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define PROTOPKG_INLINE __forceinline
#else
#define PROTOPKG_INLINE inline
#endif
#endif

namespace protopkg {

/// A vector with a fixed capacity N (counted and `remaining` arrays); no heap.
template <class T, std::size_t N> class BoundedVector {
  public:
    using value_type = T;
    static constexpr std::size_t kCapacity = N;

    constexpr std::size_t size() const {
        return size_;
    }
    static constexpr std::size_t capacity() {
        return N;
    }
    constexpr bool empty() const {
        return size_ == 0;
    }
    void clear() {
        size_ = 0;
    }
    /// Appends a copy; false (and no change) when full.
    bool push_back(const T &value) {
        if (size_ >= N) {
            return false;
        }
        items_[size_++] = value;
        return true;
    }
    /// Appends a value-initialised element and returns it; nullptr when full.
    T *grow() {
        if (size_ >= N) {
            return nullptr;
        }
        items_[size_] = T{};
        return &items_[size_++];
    }
    /// Sets the size (new elements value-initialised); false when n > N.
    bool resize(std::size_t n) {
        if (n > N) {
            return false;
        }
        for (std::size_t i = size_; i < n; ++i) {
            items_[i] = T{};
        }
        size_ = n;
        return true;
    }
    /// Unchecked access (like std::vector); use at() for a checked one.
    T &operator[](std::size_t i) {
        return items_[i];
    }
    const T &operator[](std::size_t i) const {
        return items_[i];
    }
    /// Checked access: nullptr when i >= size().
    const T *at(std::size_t i) const {
        return i < size_ ? &items_[i] : nullptr;
    }
    T *at(std::size_t i) {
        return i < size_ ? &items_[i] : nullptr;
    }
    T *begin() {
        return items_.data();
    }
    T *end() {
        return items_.data() + size_;
    }
    const T *begin() const {
        return items_.data();
    }
    const T *end() const {
        return items_.data() + size_;
    }
    friend bool operator==(const BoundedVector &a, const BoundedVector &b) {
        if (a.size_ != b.size_) {
            return false;
        }
        for (std::size_t i = 0; i < a.size_; ++i) {
            if (!(a.items_[i] == b.items_[i])) {
                return false;
            }
        }
        return true;
    }
    friend bool operator!=(const BoundedVector &a, const BoundedVector &b) {
        return !(a == b);
    }

  private:
    std::array<T, N> items_{};
    std::size_t size_ = 0;
};

/// Fixed-capacity text of an error message (no heap).
struct ErrorText {
    std::array<char, kMaxErrorPath + 128> text{};
    const char *c_str() const {
        return text.data();
    }
    std::string str() const {
        return std::string(text.data());
    }
};

/// Why field data could not be decoded (docs/conformance.md section 3), or why a field is raw.
/// Carries the parameter path and the numbers of the message; text() formats it exactly.
class DecodeError {
  public:
    enum class Kind : std::uint8_t {
        none,
        short_data,         ///< {path}: needs {n} bytes at offset {o}, {h} left
        count_exceeds,      ///< {path}: count {n} exceeds maximum {m}
        not_multiple,       ///< {path}: {h} bytes left at offset {o}, not a multiple of {n}
        invalid_bool,       ///< {path}: invalid bool value {v} at offset {o}
        no_union_member,    ///< {path}: no member for selector value {v}
        unexpected_bytes,   ///< {h} unexpected bytes at offset {o}
        unknown_set,        ///< unknown descriptor set
        unknown_descriptor, ///< unknown descriptor
    };

    Kind kind = Kind::none;
    std::uint64_t size = 0;   ///< {n}: bytes needed, count, or element size
    std::uint64_t offset = 0; ///< {o}: offset within the field data
    std::uint64_t left = 0;   ///< {h} bytes left, or {m} maximum count
    std::uint64_t value = 0;  ///< {v}: magnitude of the offending value
    bool negative = false;    ///< sign of {v}

    static DecodeError short_data(std::uint64_t n, std::uint64_t o, std::uint64_t h) {
        DecodeError e;
        e.kind = Kind::short_data;
        e.size = n;
        e.offset = o;
        e.left = h;
        return e;
    }
    static DecodeError count_exceeds(std::uint64_t n, std::uint64_t m) {
        DecodeError e;
        e.kind = Kind::count_exceeds;
        e.size = n;
        e.left = m;
        return e;
    }
    static DecodeError not_multiple(std::uint64_t h, std::uint64_t o, std::uint64_t n) {
        DecodeError e;
        e.kind = Kind::not_multiple;
        e.size = n;
        e.offset = o;
        e.left = h;
        return e;
    }
    static DecodeError invalid_bool(std::uint64_t v, std::uint64_t o) {
        DecodeError e;
        e.kind = Kind::invalid_bool;
        e.value = v;
        e.offset = o;
        return e;
    }
    static DecodeError no_union_member(std::uint64_t magnitude, bool is_negative) {
        DecodeError e;
        e.kind = Kind::no_union_member;
        e.value = magnitude;
        e.negative = is_negative;
        return e;
    }
    static DecodeError unexpected_bytes(std::uint64_t h, std::uint64_t o) {
        DecodeError e;
        e.kind = Kind::unexpected_bytes;
        e.left = h;
        e.offset = o;
        return e;
    }
    static DecodeError of(Kind k) {
        DecodeError e;
        e.kind = k;
        return e;
    }

    explicit operator bool() const {
        return kind != Kind::none;
    }
    const char *path_data() const {
        return path_.data();
    }
    std::size_t path_size() const {
        return path_len_;
    }

    /// Prefixes the path with a parameter or member name ("rate" -> "entries" + "." + "rate").
    DecodeError &enter(const char *name) {
        const bool dot = path_len_ > 0 && path_[0] != '[';
        prepend(name, std::strlen(name), dot);
        return *this;
    }
    /// Prefixes the path with an element index ("rate" -> "[2].rate").
    DecodeError &enter_index(std::size_t index) {
        char buf[24];
        const int n = std::snprintf(buf, sizeof buf, "[%llu]", static_cast<unsigned long long>(index));
        const bool dot = path_len_ > 0 && path_[0] != '[';
        prepend(buf, n > 0 ? static_cast<std::size_t>(n) : 0, dot);
        return *this;
    }

    /// The exact message of docs/conformance.md.
    ErrorText text() const {
        ErrorText t;
        char *out = t.text.data();
        const std::size_t cap = t.text.size();
        const int pl = static_cast<int>(path_len_);
        const char *p = path_.data();
        using ull = unsigned long long;
        switch (kind) {
        case Kind::none:
            std::snprintf(out, cap, "no error");
            break;
        case Kind::short_data:
            std::snprintf(out, cap, "%.*s: needs %llu bytes at offset %llu, %llu left", pl, p, ull(size),
                          ull(offset), ull(left));
            break;
        case Kind::count_exceeds:
            std::snprintf(out, cap, "%.*s: count %llu exceeds maximum %llu", pl, p, ull(size), ull(left));
            break;
        case Kind::not_multiple:
            std::snprintf(out, cap, "%.*s: %llu bytes left at offset %llu, not a multiple of %llu", pl, p,
                          ull(left), ull(offset), ull(size));
            break;
        case Kind::invalid_bool:
            std::snprintf(out, cap, "%.*s: invalid bool value %llu at offset %llu", pl, p, ull(value),
                          ull(offset));
            break;
        case Kind::no_union_member:
            std::snprintf(out, cap, "%.*s: no member for selector value %s%llu", pl, p, negative ? "-" : "",
                          ull(value));
            break;
        case Kind::unexpected_bytes:
            std::snprintf(out, cap, "%llu unexpected bytes at offset %llu", ull(left), ull(offset));
            break;
        case Kind::unknown_set:
            std::snprintf(out, cap, "unknown descriptor set");
            break;
        case Kind::unknown_descriptor:
            std::snprintf(out, cap, "unknown descriptor");
            break;
        }
        return t;
    }

  private:
    void prepend(const char *s, std::size_t n, bool dot) {
        const std::size_t extra = n + (dot ? 1 : 0);
        const std::size_t keep = path_len_ + extra > kMaxErrorPath
                                     ? (kMaxErrorPath > extra ? kMaxErrorPath - extra : 0)
                                     : path_len_;
        const std::size_t add = extra > kMaxErrorPath ? kMaxErrorPath : extra;
        std::memmove(path_.data() + add, path_.data(), keep);
        std::size_t i = 0;
        for (; i < n && i < add; ++i) {
            path_[i] = s[i];
        }
        if (dot && i < add) {
            path_[i] = '.';
        }
        path_len_ = add + keep;
    }

    std::array<char, kMaxErrorPath + 1> path_{};
    std::size_t path_len_ = 0;
};

/// The error for a union selector value that names no member (signed or unsigned).
template <class I> DecodeError no_union_member_error(I raw) {
    if constexpr (std::is_signed_v<I>) {
        if (raw < 0) {
            return DecodeError::no_union_member(
                static_cast<std::uint64_t>(-(static_cast<std::int64_t>(raw) + 1)) + 1, true);
        }
    }
    return DecodeError::no_union_member(static_cast<std::uint64_t>(raw), false);
}

/// Why a value could not be encoded.
enum class EncodeError : std::uint8_t {
    none,
    overflow,       ///< the data does not fit (field or packet too long)
    count_mismatch, ///< a counted array's size differs from its count parameter
    union_mismatch, ///< a union holds a member other than the one its selector names
    optional_gap,   ///< an optional parameter is present after an absent one
    too_short,      ///< shorter than an irregular field's size byte allows (length_byte_adjust)
    wrong_set,      ///< a typed field of another descriptor set than the packet's (PacketBuilder::add)
};

inline const char *to_string(EncodeError e) {
    switch (e) {
    case EncodeError::none:
        return "ok";
    case EncodeError::overflow:
        return "the encoded data does not fit";
    case EncodeError::count_mismatch:
        return "array size differs from its count parameter";
    case EncodeError::union_mismatch:
        return "union member does not match its selector";
    case EncodeError::optional_gap:
        return "optional parameter present after an absent one";
    case EncodeError::too_short:
        return "field data too short for its size byte";
    case EncodeError::wrong_set:
        return "the field belongs to another descriptor set";
    }
    return "?";
}

/// Bounds-checked reader over field data; offsets are relative to the start of the data.
class Reader {
  public:
    Reader(const std::uint8_t *data, std::size_t size) : data_(data), size_(size) {}
    std::size_t offset() const {
        return pos_;
    }
    std::size_t left() const {
        return size_ - pos_;
    }
    /// True when n bytes are left; otherwise sets a short_data error.
    bool need(std::size_t n, DecodeError &err) const {
        if (left() < n) {
            err = DecodeError::short_data(n, pos_, left());
            return false;
        }
        return true;
    }
    /// Takes an n-byte unsigned integer (n <= 8) in the protocol's byte order; call need() first.
    std::uint64_t take_uint(std::size_t n) {
        const std::uint8_t *const p = data_ + pos_;
        // The common sizes as straight expressions (one load and a byte swap), the rest a loop.
        switch (n) {
        case 2:
            pos_ += 2;
            return load2(p);
        case 4:
            pos_ += 4;
            return load4(p);
        case 8:
            pos_ += 8;
            if constexpr (kBigEndian) {
                return load4(p) << 32 | load4(p + 4);
            } else {
                return load4(p + 4) << 32 | load4(p);
            }
        default:
            break;
        }
        std::uint64_t v = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint64_t b = p[i];
            if constexpr (kBigEndian) {
                v = (v << 8) | b;
            } else {
                v |= b << (8 * i);
            }
        }
        pos_ += n;
        return v;
    }
    PROTOPKG_INLINE static std::uint64_t load2(const std::uint8_t *p) {
        if constexpr (kBigEndian) {
            return static_cast<std::uint64_t>(p[0]) << 8 | p[1];
        } else {
            return static_cast<std::uint64_t>(p[1]) << 8 | p[0];
        }
    }
    PROTOPKG_INLINE static std::uint64_t load4(const std::uint8_t *p) {
        if constexpr (kBigEndian) {
            return static_cast<std::uint64_t>(p[0]) << 24 | static_cast<std::uint64_t>(p[1]) << 16 |
                   static_cast<std::uint64_t>(p[2]) << 8 | p[3];
        } else {
            return static_cast<std::uint64_t>(p[3]) << 24 | static_cast<std::uint64_t>(p[2]) << 16 |
                   static_cast<std::uint64_t>(p[1]) << 8 | p[0];
        }
    }
    /// Takes n raw bytes; call need() first.
    const std::uint8_t *take(std::size_t n) {
        const std::uint8_t *p = data_ + pos_;
        pos_ += n;
        return p;
    }

  private:
    const std::uint8_t *data_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

/// Bounds-checked writer; the first problem is kept in error() and later writes are dropped.
class Writer {
  public:
    Writer(std::uint8_t *data, std::size_t capacity) : data_(data), capacity_(capacity) {}
    std::size_t size() const {
        return size_;
    }
    EncodeError error() const {
        return error_;
    }
    void fail(EncodeError e) {
        if (error_ == EncodeError::none) {
            error_ = e;
        }
    }
    /// Writes the low n bytes (n <= 8) of v in the protocol's byte order.
    void put_uint(std::size_t n, std::uint64_t v) {
        if (!room(n)) {
            return;
        }
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t shift = kBigEndian ? 8 * (n - 1 - i) : 8 * i;
            data_[size_ + i] = static_cast<std::uint8_t>((v >> shift) & 0xFFu);
        }
        size_ += n;
    }
    void put_bytes(const void *p, std::size_t n) {
        if (n == 0 || !room(n)) {
            return;
        }
        std::memcpy(data_ + size_, p, n);
        size_ += n;
    }

  private:
    bool room(std::size_t n) {
        if (error_ != EncodeError::none) {
            return false;
        }
        if (capacity_ - size_ < n) {
            fail(EncodeError::overflow);
            return false;
        }
        return true;
    }
    std::uint8_t *data_;
    std::size_t capacity_;
    std::size_t size_ = 0;
    EncodeError error_ = EncodeError::none;
};

/// An N-byte unsigned integer (N in 1, 2, 4, 8) in the protocol's byte order, read from p
/// without checks (the caller knows N bytes are there): one load and a byte swap.
template <std::size_t N> PROTOPKG_INLINE std::uint64_t load_uint(const std::uint8_t *p) {
    static_assert(N == 1 || N == 2 || N == 4 || N == 8, "load_uint: 1, 2, 4 or 8 bytes");
    if constexpr (N == 1) {
        return p[0];
    } else if constexpr (N == 2) {
        return Reader::load2(p);
    } else if constexpr (N == 4) {
        return Reader::load4(p);
    } else if constexpr (kBigEndian) {
        return Reader::load4(p) << 32 | Reader::load4(p + 4);
    } else {
        return Reader::load4(p + 4) << 32 | Reader::load4(p);
    }
}

/// Binary codec of a wire type: read(Reader&, T&, DecodeError&) and write(Writer&, const T&).
/// kFixedSize/kSize give the encoded size when it does not depend on the value.
/// Specialised here for primitives and enums, and in the generated headers for every type and layout.
template <class T, class Enable = void> struct Codec;

/// Plain<V>: V (a parameter's value type: a wire type or a std::array of one) is decoded by
/// straight loads when its data has exactly Plain<V>::kSize bytes: every byte pattern of that
/// size is a valid value (no bool, union, optional or variable-length array inside), so the
/// checked Codec<T>::read cannot fail on it and gives the same value. Codec<T>::kPlain and
/// Codec<T>::load(p, v) (reads kSize bytes at p, no checks) say so for a wire type.
template <class V, class Enable = void> struct Plain {
    static constexpr bool kPlain = false;
    static constexpr std::size_t kSize = 0;
};
template <class V> struct Plain<V, std::enable_if_t<Codec<V>::kPlain>> {
    static constexpr bool kPlain = true;
    static constexpr std::size_t kSize = Codec<V>::kSize;
    PROTOPKG_INLINE static void load(const std::uint8_t *p, V &v) {
        Codec<V>::load(p, v);
    }
};
template <class E, std::size_t N> struct Plain<std::array<E, N>, std::enable_if_t<Plain<E>::kPlain>> {
    static constexpr bool kPlain = true;
    static constexpr std::size_t kSize = N * Plain<E>::kSize;
    PROTOPKG_INLINE static void load(const std::uint8_t *p, std::array<E, N> &v) {
        for (std::size_t i = 0; i < N; ++i) {
            Plain<E>::load(p + i * Plain<E>::kSize, v[i]);
        }
    }
};

template <class T>
struct Codec<
    T, std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool> && !std::is_same_v<T, char>>> {
    static constexpr bool kFixedSize = true;
    static constexpr std::size_t kSize = sizeof(T);
    static constexpr bool kPlain = true;
    PROTOPKG_INLINE static void load(const std::uint8_t *p, T &v) {
        using U = std::make_unsigned_t<T>;
        const U u = static_cast<U>(load_uint<sizeof(T)>(p));
        std::memcpy(&v, &u, sizeof v);
    }
    static bool read(Reader &r, T &v, DecodeError &err) {
        if (!r.need(sizeof(T), err)) {
            return false;
        }
        using U = std::make_unsigned_t<T>;
        const U u = static_cast<U>(r.take_uint(sizeof(T)));
        std::memcpy(&v, &u, sizeof v); // two's complement reinterpretation, no overflow
        return true;
    }
    static void write(Writer &w, const T &v) {
        using U = std::make_unsigned_t<T>;
        U u;
        std::memcpy(&u, &v, sizeof u);
        w.put_uint(sizeof(T), static_cast<std::uint64_t>(u));
    }
};

template <class T> struct Codec<T, std::enable_if_t<std::is_enum_v<T>>> {
    using U = std::underlying_type_t<T>;
    static constexpr bool kFixedSize = true;
    static constexpr std::size_t kSize = sizeof(U);
    static constexpr bool kPlain = true;
    PROTOPKG_INLINE static void load(const std::uint8_t *p, T &v) {
        U u{};
        Codec<U>::load(p, u);
        v = static_cast<T>(u);
    }
    static bool read(Reader &r, T &v, DecodeError &err) {
        U u{};
        if (!Codec<U>::read(r, u, err)) {
            return false;
        }
        v = static_cast<T>(u); // enum classes hold every value of their underlying type
        return true;
    }
    static void write(Writer &w, const T &v) {
        Codec<U>::write(w, static_cast<U>(v));
    }
};

template <> struct Codec<bool> {
    static constexpr bool kFixedSize = true;
    static constexpr std::size_t kSize = 1;
    static bool read(Reader &r, bool &v, DecodeError &err) {
        if (!r.need(1, err)) {
            return false;
        }
        const std::size_t at = r.offset();
        const std::uint64_t b = r.take_uint(1);
        if (b > 1) {
            err = DecodeError::invalid_bool(b, at);
            return false;
        }
        v = b == 1;
        return true;
    }
    static void write(Writer &w, const bool &v) {
        w.put_uint(1, v ? 1 : 0);
    }
};

template <> struct Codec<char> {
    static constexpr bool kFixedSize = true;
    static constexpr std::size_t kSize = 1;
    static constexpr bool kPlain = true;
    PROTOPKG_INLINE static void load(const std::uint8_t *p, char &v) {
        std::memcpy(&v, p, 1);
    }
    static bool read(Reader &r, char &v, DecodeError &err) {
        if (!r.need(1, err)) {
            return false;
        }
        const std::uint8_t b = *r.take(1);
        std::memcpy(&v, &b, 1);
        return true;
    }
    static void write(Writer &w, const char &v) {
        w.put_bytes(&v, 1);
    }
};

template <> struct Codec<float> {
    static constexpr bool kFixedSize = true;
    static constexpr std::size_t kSize = 4;
    static constexpr bool kPlain = true;
    PROTOPKG_INLINE static void load(const std::uint8_t *p, float &v) {
        const auto bits = static_cast<std::uint32_t>(load_uint<4>(p));
        std::memcpy(&v, &bits, 4); // keeps NaN payloads
    }
    static bool read(Reader &r, float &v, DecodeError &err) {
        if (!r.need(4, err)) {
            return false;
        }
        const std::uint32_t bits = static_cast<std::uint32_t>(r.take_uint(4));
        std::memcpy(&v, &bits, 4); // keeps NaN payloads
        return true;
    }
    static void write(Writer &w, const float &v) {
        std::uint32_t bits;
        std::memcpy(&bits, &v, 4);
        w.put_uint(4, bits);
    }
};

template <> struct Codec<double> {
    static constexpr bool kFixedSize = true;
    static constexpr std::size_t kSize = 8;
    static constexpr bool kPlain = true;
    PROTOPKG_INLINE static void load(const std::uint8_t *p, double &v) {
        const std::uint64_t bits = load_uint<8>(p);
        std::memcpy(&v, &bits, 8); // keeps NaN payloads
    }
    static bool read(Reader &r, double &v, DecodeError &err) {
        if (!r.need(8, err)) {
            return false;
        }
        const std::uint64_t bits = r.take_uint(8);
        std::memcpy(&v, &bits, 8);
        return true;
    }
    static void write(Writer &w, const double &v) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, 8);
        w.put_uint(8, bits);
    }
};

// ---- parameter helpers used by the generated codecs

template <class T> bool read_value(Reader &r, T &v, DecodeError &err) {
    return Codec<T>::read(r, v, err);
}
template <class T> void write_value(Writer &w, const T &v) {
    Codec<T>::write(w, v);
}

/// A string of exactly N bytes, kept verbatim (padding included).
template <std::size_t N> bool read_string(Reader &r, std::array<char, N> &v, DecodeError &err) {
    if (!r.need(N, err)) {
        return false;
    }
    std::memcpy(v.data(), r.take(N), N);
    return true;
}
template <std::size_t N> void write_string(Writer &w, const std::array<char, N> &v) {
    w.put_bytes(v.data(), N);
}

template <class T, std::size_t N> bool read_fixed(Reader &r, std::array<T, N> &v, DecodeError &err) {
    for (std::size_t i = 0; i < N; ++i) {
        if (!Codec<T>::read(r, v[i], err)) {
            err.enter_index(i);
            return false;
        }
    }
    return true;
}
template <class T, std::size_t N> void write_fixed(Writer &w, const std::array<T, N> &v) {
    for (const T &item : v) {
        Codec<T>::write(w, item);
    }
}

/// An array whose element count is an earlier parameter.
template <class T, std::size_t M>
bool read_counted(Reader &r, BoundedVector<T, M> &v, std::uint64_t count, DecodeError &err) {
    v.clear();
    if (count > M) {
        err = DecodeError::count_exceeds(count, M);
        return false;
    }
    for (std::uint64_t i = 0; i < count; ++i) {
        T *item = v.grow();
        if (!Codec<T>::read(r, *item, err)) {
            err.enter_index(static_cast<std::size_t>(i));
            return false;
        }
    }
    return true;
}
template <class T, std::size_t M>
void write_counted(Writer &w, const BoundedVector<T, M> &v, std::uint64_t count) {
    if (count != v.size()) {
        w.fail(EncodeError::count_mismatch);
        return;
    }
    for (const T &item : v) {
        Codec<T>::write(w, item);
    }
}

/// An array that runs to the end of the field data.
template <class T, std::size_t M> bool read_remaining(Reader &r, BoundedVector<T, M> &v, DecodeError &err) {
    v.clear();
    if constexpr (Codec<T>::kFixedSize && Codec<T>::kSize > 0) {
        constexpr std::size_t n = Codec<T>::kSize;
        if (r.left() % n != 0) {
            err = DecodeError::not_multiple(r.left(), r.offset(), n);
            return false;
        }
        if (r.left() / n > M) {
            err = DecodeError::count_exceeds(r.left() / n, M);
            return false;
        }
    }
    while (r.left() > 0) {
        T *item = v.grow();
        if (item == nullptr) {
            err = DecodeError::count_exceeds(M + 1, M);
            return false;
        }
        if (!Codec<T>::read(r, *item, err)) {
            err.enter_index(v.size() - 1);
            return false;
        }
    }
    return true;
}
template <class T, std::size_t M> void write_remaining(Writer &w, const BoundedVector<T, M> &v) {
    for (const T &item : v) {
        Codec<T>::write(w, item);
    }
}

/// Decodes one layout (all of `size` bytes): leftover bytes are an error.
template <class T> bool decode(const std::uint8_t *data, std::size_t size, T &out, DecodeError &err) {
    if constexpr (Plain<T>::kPlain) {
        if (size == Plain<T>::kSize) { // the straight path: sets every member, cannot fail
            Plain<T>::load(data, out);
            return true;
        }
    }
    Reader r(data, size);
    out = T{};
    if (!Codec<T>::read(r, out, err)) {
        return false;
    }
    if (r.left() != 0) {
        err = DecodeError::unexpected_bytes(r.left(), r.offset());
        return false;
    }
    return true;
}

/// Encodes one layout into out[0..capacity); `written` is the data size on success.
template <class T>
EncodeError encode(const T &value, std::uint8_t *out, std::size_t capacity, std::size_t &written) {
    Writer w(out, capacity);
    Codec<T>::write(w, value);
    written = w.error() == EncodeError::none ? w.size() : 0;
    return w.error();
}

} // namespace protopkg
