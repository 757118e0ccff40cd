// Samples: continuation packets grouped by their shared timestamp (docs/conformance.md section 6).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "protopkg/framing.hpp"
#include "protopkg/packet.hpp"

namespace protopkg {

/// The key of a packet (bytes of its leading shared timestamp fields) and its leading shared run.
struct SampleKey {
    std::array<std::uint8_t, sample_rule::kMaxKey> bytes{};
    std::size_t size = 0;          ///< 0: no key
    std::size_t shared_prefix = 0; ///< payload bytes of the leading shared run

    bool operator==(const SampleKey &o) const {
        return size == o.size && std::memcmp(bytes.data(), o.bytes.data(), size) == 0;
    }
};

inline bool is_data_set(std::uint8_t set) {
    for (std::uint8_t s : sample_rule::kDataSets) {
        if (s == set) {
            return true;
        }
    }
    return false;
}

inline SampleKey sample_key(const PacketView &packet) {
    SampleKey key;
    std::array<bool, sample_rule::kTimestamps.size() + 1> seen{};
    FieldIterator it(packet);
    FieldEntry e;
    while (it.next(e) && e.kind == FieldEntry::Kind::field && sample_rule::is_shared(e.descriptor)) {
        for (std::size_t t = 0; t < sample_rule::kTimestamps.size(); ++t) {
            const auto &stamp = sample_rule::kTimestamps[t];
            if (stamp.descriptor == e.descriptor && stamp.size == e.size && !seen[t]) {
                const std::size_t n = kFieldHeaderSize + e.size;
                seen[t] = true;
                if (key.size + n <= key.bytes.size()) {
                    std::memcpy(key.bytes.data() + key.size, packet.payload() + e.payload_offset, n);
                    key.size += n;
                }
                break;
            }
        }
        key.shared_prefix = e.payload_offset + kFieldHeaderSize + e.size;
    }
    return key;
}

/// Where a data packet belongs: its sample number and whether it continues an earlier packet.
struct SamplePlace {
    std::uint64_t number = 0;
    bool continues = false;
    std::size_t shared_prefix = 0;
};

/// Numbers the samples of complete packets; fixed state, one slot per data set.
class SampleTracker {
  public:
    /// The place of a data-set packet; std::nullopt for other packets.
    std::optional<SamplePlace> feed(const PacketView &packet) {
        std::size_t i = 0;
        while (i < sample_rule::kDataSets.size() && sample_rule::kDataSets[i] != packet.set()) {
            ++i;
        }
        if (i == sample_rule::kDataSets.size()) {
            return std::nullopt;
        }
        Slot &slot = slots_[i];
        const SampleKey key = sample_key(packet);
        SamplePlace place;
        place.shared_prefix = key.shared_prefix;
        if (key.size > 0 && slot.used && slot.key == key) {
            place.number = slot.number;
            place.continues = true;
            return place;
        }
        slot.used = true;
        slot.number = next_++;
        slot.key = key;
        place.number = slot.number;
        return place;
    }

  private:
    struct Slot {
        bool used = false;
        std::uint64_t number = 0;
        SampleKey key;
    };
    std::array<Slot, sample_rule::kDataSets.size()> slots_{};
    std::uint64_t next_ = 0;
};

/// One sample: its set, number and the bytes of its packets.
struct Sample {
    std::uint64_t number = 0;
    std::uint8_t set = 0;
    std::vector<std::uint64_t> offsets;             ///< stream offset of each packet
    std::vector<std::vector<std::uint8_t>> packets; ///< complete packets, in order
    std::vector<std::size_t> skip;                  ///< payload bytes to skip (copies) per packet

    /// Calls fn(const FieldEntry&) for every field of the sample: the first packet's fields, then
    /// each continuation packet's fields after its leading shared run.
    template <class Fn> void for_each_field(Fn &&fn) const {
        for (std::size_t k = 0; k < packets.size(); ++k) {
            const PacketView view{packets[k].data(), packets[k].size()};
            FieldIterator it(view.set(), view.payload() + skip[k], view.payload_size() - skip[k]);
            FieldEntry e;
            while (it.next(e)) {
                e.payload_offset += skip[k];
                fn(static_cast<const FieldEntry &>(e));
            }
        }
    }
};

/// Groups data packets into samples; on_sample(Sample&&) is called when a sample is complete
/// (the next packet of its set starts another one) and, for the rest, by flush().
class SampleGrouper {
  public:
    template <class OnSample>
    void feed(const PacketView &packet, std::uint64_t offset, OnSample &&on_sample) {
        const std::optional<SamplePlace> place = tracker_.feed(packet);
        if (!place) {
            return;
        }
        std::optional<Sample> &open = open_[slot_of(packet.set())];
        if (place->continues && open) {
            open->offsets.push_back(offset);
            open->packets.emplace_back(packet.data, packet.data + packet.size);
            open->skip.push_back(place->shared_prefix);
            return;
        }
        if (open) {
            on_sample(std::move(*open));
        }
        open.emplace();
        open->number = place->number;
        open->set = packet.set();
        open->offsets.push_back(offset);
        open->packets.emplace_back(packet.data, packet.data + packet.size);
        open->skip.push_back(0);
    }

    /// Delivers the samples still open, in order of their numbers.
    template <class OnSample> void flush(OnSample &&on_sample) {
        for (;;) {
            std::optional<Sample> *first = nullptr;
            for (auto &o : open_) {
                if (o && (first == nullptr || o->number < (*first)->number)) {
                    first = &o;
                }
            }
            if (first == nullptr) {
                return;
            }
            on_sample(std::move(**first));
            first->reset();
        }
    }

  private:
    static std::size_t slot_of(std::uint8_t set) {
        std::size_t i = 0;
        while (i < sample_rule::kDataSets.size() && sample_rule::kDataSets[i] != set) {
            ++i;
        }
        return i;
    }
    SampleTracker tracker_;
    std::array<std::optional<Sample>, sample_rule::kDataSets.size()> open_{};
};

} // namespace protopkg
