// Stream parser of docs/conformance.md section 1: fed arbitrary chunks, it reports packets and
// runs of skipped bytes exactly as if it had seen the whole stream at once. Its state is one
// maximum packet or foreign frame (kParserCapacity bytes); skipped bytes are reported by offset and count
// only (a run of any length costs two integers).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "protopkg/checksum.hpp"
#include "protopkg/framing.hpp"
#include "protopkg/packet.hpp"

namespace protopkg {

struct StreamEvent {
    /// nmea, rtcm: an NMEA-0183 sentence ('$' to LF) or an RTCM3 frame (0xD3 to its CRC) between
    /// packets (kForeignNmea, kForeignRtcm3; docs/conformance.md section 1), its bytes in `packet`.
    enum class Kind : std::uint8_t { packet, skip, nmea, rtcm };
    Kind kind = Kind::packet;
    std::uint64_t offset = 0; ///< stream offset of the packet, frame or first skipped byte
    std::uint64_t count = 0;  ///< skipped bytes (skip events)
    PacketView packet;        ///< packet or frame bytes, valid during the callback only

    /// The message number of an rtcm event's frame (the first 12 bits of its payload).
    unsigned rtcm_type() const {
        return static_cast<unsigned>(packet.data[3]) << 4 | static_cast<unsigned>(packet.data[4]) >> 4;
    }
};

/// Foreign frames (docs/conformance.md section 1): where the parser would skip bytes, a whole
/// NMEA-0183 sentence or RTCM3 frame is reported instead; a candidate that fails stays skipped
/// bytes, one byte at a time. Never on the packet path.
namespace foreign {
inline constexpr std::size_t kWait = static_cast<std::size_t>(-1);

inline bool starts(std::uint8_t b) {
    return (kForeignNmea && (b == 0x24 || b == 0x21)) || (kForeignRtcm3 && b == 0xD3);
}

/// Index in p[0..n) of the first byte that starts a foreign frame, else n.
inline std::size_t next(const std::uint8_t *p, std::size_t n) {
    std::size_t i = 0;
    while (i < n && !starts(p[i])) {
        ++i;
    }
    return i;
}

/// CRC-24Q of RTCM3: polynomial 0x1864CFB, initial value 0, not reflected.
inline std::uint32_t crc24q(const std::uint8_t *p, std::size_t n) {
    std::uint32_t crc = 0;
    for (std::size_t i = 0; i < n; ++i) {
        crc ^= static_cast<std::uint32_t>(p[i]) << 16;
        for (int k = 0; k < 8; ++k) {
            crc <<= 1;
            if ((crc & 0x1000000u) != 0) {
                crc ^= 0x1864CFBu;
            }
        }
    }
    return crc;
}

inline int hex_digit(std::uint8_t c) {
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    return -1;
}

/// The foreign frame at p[0] (a start byte) with n bytes available: its length when it is whole
/// and valid, 0 when it is not one, kWait when more bytes decide.
inline std::size_t frame(const std::uint8_t *p, std::size_t n) {
    if (p[0] == 0xD3) {
        if (n < 3) {
            return kWait;
        }
        if ((p[1] & 0xFC) != 0) {
            return 0;
        }
        const std::size_t length = static_cast<std::size_t>(p[1] & 3) << 8 | p[2];
        const std::size_t total = 3 + length + 3;
        if (length < 2) {
            return 0; // no message number
        }
        if (n < total) {
            return kWait;
        }
        const std::uint32_t crc = static_cast<std::uint32_t>(p[total - 3]) << 16 |
                                  static_cast<std::uint32_t>(p[total - 2]) << 8 | p[total - 1];
        return crc24q(p, total - 3) == crc ? total : 0;
    }
    const std::size_t lim = kNmeaMax > 4 ? kNmeaMax - 4 : 1; // the '*' stands before lim
    std::size_t j = 1;
    unsigned x = 0;
    while (j < n && j < lim && p[j] >= 0x20 && p[j] <= 0x7E && p[j] != '$' && p[j] != '!' && p[j] != '*') {
        x ^= p[j++];
    }
    if (j == lim) {
        return 0; // overlong
    }
    if (j == n) {
        return kWait;
    }
    if (p[j] != '*') {
        return 0;
    }
    if (n < j + 5) {
        return kWait;
    }
    const int hi = hex_digit(p[j + 1]);
    const int lo = hex_digit(p[j + 2]);
    if (hi < 0 || lo < 0 || p[j + 3] != '\r' || p[j + 4] != '\n' ||
        static_cast<unsigned>(hi << 4 | lo) != x) {
        return 0;
    }
    return j + 5;
}

/// Bytes the undecided candidate at p[0] (n bytes) needs at most before it is decided.
inline std::size_t wanted(const std::uint8_t *p, std::size_t n) {
    std::size_t total = kNmeaMax;
    if (p[0] == 0xD3) {
        total = n < 3 ? 3 : 3 + (static_cast<std::size_t>(p[1] & 3) << 8 | p[2]) + 3;
    }
    return total > n ? total - n : 1;
}
} // namespace foreign

class StreamParser {
  public:
    /// Feeds bytes; on_event(const StreamEvent&) is called for every packet and skip run found.
    template <class Handler> void feed(const std::uint8_t *data, std::size_t size, Handler &&on_event) {
        while (size > 0) {
            if (len_ == 0) {
                // Nothing buffered: packets are checked and reported in place; what is left is
                // a candidate waiting for more input, shorter than a maximum packet.
                const std::size_t done = scan(data, size, on_event);
                data += done;
                size -= done;
                std::memcpy(buf_.data(), data, size);
                start_ = 0;
                len_ = size;
                return;
            }
            // Complete the buffered candidate, no more: once the buffer is empty again the fast
            // path takes over.
            std::size_t n = wanted();
            if (n > size) {
                n = size;
            }
            if (start_ + len_ + n > buf_.size()) {
                std::memmove(buf_.data(), buf_.data() + start_, len_);
                start_ = 0;
            }
            std::memcpy(buf_.data() + start_ + len_, data, n);
            len_ += n;
            data += n;
            size -= n;
            process(on_event, false);
        }
    }

    /// End of input: the same loop, but a candidate that would wait for more input is a false
    /// sync (skip one byte and go on), so no complete packet behind it is lost. The pending skip
    /// run is reported. The parser can then be fed a new stream (offsets continue).
    template <class Handler> void flush(Handler &&on_event) {
        process(on_event, true);
        emit_skip(on_event);
        start_ = 0;
    }

    /// Stream offset of the next byte to be fed.
    std::uint64_t position() const {
        return base_ + len_;
    }

    /// Stream offset from which the caller must keep its input to print the bytes of skip runs
    /// still to be reported: the pending run's first byte, else the first undecided byte.
    std::uint64_t retain_from() const {
        return skip_count_ > 0 ? skip_offset_ : base_;
    }

    /// True while the parser waits for more input at a candidate (a partial sync, header or packet).
    bool buffered() const {
        return len_ > 0;
    }

    /// Stream offset of the candidate it waits at (when buffered()).
    std::uint64_t buffered_at() const {
        return base_;
    }

    /// The look-ahead rule of docs/conformance.md section 8 (the session calls it once the wait at
    /// the candidate has lasted longer than the inter-packet timeout): the first position j > 0 in
    /// the buffered bytes where a sync sequence starts a complete packet with a valid checksum (the
    /// checks of process(), on bytes already buffered only). When there is one, the bytes before
    /// it join the pending skip run, and parsing resumes there (the run, the packet and what
    /// follows are reported); true. When there is none nothing changes (a slow packet keeps
    /// waiting); false.
    template <class Handler> bool look_ahead(Handler &&on_event) {
        const std::uint8_t *p = buf_.data() + start_;
        for (std::size_t j = 1; j + kHeaderSize <= len_; ++j) {
            if (p[j] != kSync[0] || std::memcmp(p + j, kSync.data(), kSyncSize) != 0) {
                continue;
            }
            const std::size_t length = p[j + kLengthOffset];
            if (length > kMaxPayload) {
                continue;
            }
            const std::size_t body = kHeaderSize + length;
            if (j + body + kChecksumSize > len_ || !fletcher16_matches(p + j, body, p + j + body)) {
                continue;
            }
            skip(j);
            process(on_event, false);
            return true;
        }
        return false;
    }

    /// Bytes in the skip run not yet reported (it ends at the next packet, or at flush()).
    std::uint64_t pending_skip() const {
        return skip_count_;
    }

    /// Reports the first `piece` bytes of the pending skip run now (piece <= pending_skip()); the
    /// rest stays pending, as a run starting right after it.
    template <class Handler> void report_skip_piece(std::uint64_t piece, Handler &&on_event) {
        emit_skip_run(on_event, skip_offset_, piece);
        skip_offset_ += piece;
        skip_count_ -= piece;
    }

  private:
    /// Bytes the buffered candidate (at buf_[start_]) needs before process() can decide on it.
    std::size_t wanted() const {
        if constexpr (kForeignNmea || kForeignRtcm3) {
            if (foreign::starts(buf_[start_])) {
                return foreign::wanted(buf_.data() + start_, len_);
            }
        }
        if (len_ < kHeaderSize) {
            return kHeaderSize - len_;
        }
        const std::size_t total = kHeaderSize + buf_[start_ + kLengthOffset] + kChecksumSize;
        return total > len_ ? total - len_ : 1;
    }

    /// The decisions of process() made in place on the caller's bytes (nothing is buffered).
    /// Returns the bytes consumed; base_ follows them. The pending skip run lives in locals
    /// here (the handler's stores could otherwise alias the members and force them to memory
    /// on every packet).
    template <class Handler> std::size_t scan(const std::uint8_t *data, std::size_t size, Handler &on_event) {
        const std::uint64_t base = base_;
        std::uint64_t skip_offset = skip_offset_;
        std::uint64_t skip_count = skip_count_;
        std::size_t pos = 0;
        while (pos < size) {
            const std::uint8_t *p = data + pos;
            const std::size_t left = size - pos;
            std::size_t skipped = 1; // a false sync: resynchronise at the next byte
            if (p[0] != kSync[0]) {
                skipped = find_sync_byte(p, left);
                if constexpr (kForeignNmea || kForeignRtcm3) {
                    const std::size_t s = foreign::next(p, skipped);
                    if (s < skipped) {
                        if (s > 0) {
                            if (skip_count == 0) {
                                skip_offset = base + pos;
                            }
                            skip_count += s;
                            pos += s;
                        }
                        const std::size_t r = foreign::frame(data + pos, size - pos);
                        if (r == foreign::kWait) {
                            break; // an undecided frame at the end: buffered
                        }
                        if (r != 0) {
                            if (skip_count > 0) {
                                emit_skip_run(on_event, skip_offset, skip_count);
                                skip_count = 0;
                            }
                            emit_foreign(on_event, data + pos, r, base + pos);
                            pos += r;
                            continue;
                        }
                        skipped = 1; // not a frame: its first byte is skipped
                    }
                }
            } else if (left >= kHeaderSize) {
                const std::size_t length = p[kLengthOffset];
                if (std::memcmp(p + 1, kSync.data() + 1, kSyncSize - 1) == 0 && length <= kMaxPayload) {
                    const std::size_t body = kHeaderSize + length;
                    if (left < body + kChecksumSize) {
                        break; // incomplete packet: buffered
                    }
                    if (fletcher16_matches(p, body, p + body)) {
                        if (skip_count > 0) {
                            emit_skip_run(on_event, skip_offset, skip_count);
                            skip_count = 0;
                        }
                        StreamEvent e;
                        e.kind = StreamEvent::Kind::packet;
                        e.offset = base + pos;
                        e.packet = PacketView{p, body + kChecksumSize};
                        on_event(static_cast<const StreamEvent &>(e));
                        pos += body + kChecksumSize;
                        continue;
                    }
                }
            } else if (std::memcmp(p, kSync.data(), left < kSyncSize ? left : kSyncSize) == 0) {
                // A partial sync or header at the end waits in the buffer (unless it already
                // differs from the sync sequence).
                break;
            }
            if (skip_count == 0) {
                skip_offset = base + pos;
            }
            skip_count += skipped;
            pos += skipped;
        }
        skip_offset_ = skip_offset;
        skip_count_ = skip_count;
        base_ = base + pos;
        return pos;
    }

    /// Index of the first byte equal to kSync[0] in p[0..n), else n. The bytes after a packet
    /// are mostly the next packet's sync or a few bytes of garbage: one 16-byte compare finds it
    /// without a library call where the vector path exists.
    static std::size_t find_sync_byte(const std::uint8_t *p, std::size_t n) {
#if defined(PROTOPKG_FLETCHER_SSE2)
        if (n >= 16) {
            const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i *>(p));
            const int hits = _mm_movemask_epi8(_mm_cmpeq_epi8(v, _mm_set1_epi8(static_cast<char>(kSync[0]))));
            if (hits != 0) {
                return static_cast<std::size_t>(__builtin_ctz(static_cast<unsigned>(hits)));
            }
            const void *q = std::memchr(p + 16, kSync[0], n - 16);
            return q != nullptr ? static_cast<std::size_t>(static_cast<const std::uint8_t *>(q) - p) : n;
        }
#endif
        const void *q = std::memchr(p, kSync[0], n);
        return q != nullptr ? static_cast<std::size_t>(static_cast<const std::uint8_t *>(q) - p) : n;
    }

    template <class Handler>
    static void emit_foreign(Handler &on_event, const std::uint8_t *p, std::size_t n, std::uint64_t offset) {
        StreamEvent e;
        e.kind = p[0] == 0xD3 ? StreamEvent::Kind::rtcm : StreamEvent::Kind::nmea;
        e.offset = offset;
        e.packet = PacketView{p, n};
        on_event(static_cast<const StreamEvent &>(e));
    }

    template <class Handler>
    static void emit_skip_run(Handler &on_event, std::uint64_t offset, std::uint64_t count) {
        StreamEvent e;
        e.kind = StreamEvent::Kind::skip;
        e.offset = offset;
        e.count = count;
        on_event(static_cast<const StreamEvent &>(e));
    }

    void skip_at(std::uint64_t offset, std::size_t n) {
        if (skip_count_ == 0) {
            skip_offset_ = offset;
        }
        skip_count_ += n;
    }

    template <class Handler> void process(Handler &on_event, bool final) {
        for (;;) {
            const std::uint8_t *p = buf_.data() + start_;
            std::size_t i = 0;
            bool found = false;
            while (i + kSyncSize <= len_) {
                if (std::memcmp(p + i, kSync.data(), kSyncSize) == 0) {
                    found = true;
                    break;
                }
                ++i;
            }
            if constexpr (kForeignNmea || kForeignRtcm3) {
                const std::size_t gap = found ? i : final ? len_ : len_ - partial_sync_tail(p, len_);
                const std::size_t s = foreign::next(p, gap);
                if (s < gap) {
                    skip(s);
                    p = buf_.data() + start_;
                    std::size_t r = foreign::frame(p, len_);
                    if (r == foreign::kWait) {
                        if (!final) {
                            return; // an undecided frame: wait
                        }
                        r = 0;
                    }
                    if (r == 0) {
                        skip(1); // not a frame: its first byte is skipped
                        continue;
                    }
                    emit_skip(on_event);
                    emit_foreign(on_event, p, r, base_);
                    start_ += r;
                    len_ -= r;
                    base_ += r;
                    continue;
                }
            }
            if (!found) {
                skip(final ? len_ : len_ - partial_sync_tail(p, len_));
                return;
            }
            if (i > 0) {
                skip(i);
                p = buf_.data() + start_;
            }
            if (len_ < kHeaderSize) {
                if (final) {
                    skip(1);
                    continue;
                }
                return;
            }
            const std::size_t length = p[kLengthOffset];
            if (length > kMaxPayload) {
                skip(1);
                continue;
            }
            const std::size_t total = kHeaderSize + length + kChecksumSize;
            if (len_ < total) {
                if (final) {
                    skip(1);
                    continue;
                }
                return;
            }
            if (!fletcher16_matches(p, kHeaderSize + length, p + kHeaderSize + length)) {
                skip(1);
                continue;
            }
            emit_skip(on_event);
            StreamEvent e;
            e.kind = StreamEvent::Kind::packet;
            e.offset = base_;
            e.packet = PacketView{p, total};
            on_event(static_cast<const StreamEvent &>(e));
            start_ += total;
            len_ -= total;
            base_ += total;
        }
    }

    /// Length of the longest suffix of p[0..n) that is a proper prefix of the sync sequence.
    static std::size_t partial_sync_tail(const std::uint8_t *p, std::size_t n) {
        std::size_t k = kSyncSize - 1 < n ? kSyncSize - 1 : n;
        for (; k > 0; --k) {
            if (std::memcmp(p + n - k, kSync.data(), k) == 0) {
                return k;
            }
        }
        return 0;
    }

    void skip(std::size_t n) {
        if (n == 0) {
            return;
        }
        if (skip_count_ == 0) {
            skip_offset_ = base_;
        }
        skip_count_ += n;
        start_ += n;
        len_ -= n;
        base_ += n;
    }

    template <class Handler> void emit_skip(Handler &on_event) {
        if (skip_count_ == 0) {
            return;
        }
        const std::uint64_t count = skip_count_;
        skip_count_ = 0;
        emit_skip_run(on_event, skip_offset_, count);
    }

    std::array<std::uint8_t, kParserCapacity> buf_{}; ///< a maximum packet, or a longer foreign frame
    std::size_t start_ = 0;                           ///< first unconsumed byte in buf_
    std::size_t len_ = 0;                             ///< unconsumed bytes in buf_
    std::uint64_t base_ = 0;                          ///< stream offset of buf_[start_]
    std::uint64_t skip_offset_ = 0;
    std::uint64_t skip_count_ = 0;
};

} // namespace protopkg
