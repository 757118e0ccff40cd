// The host clock model (docs/time.md): offset and drift of a device's reference clock against the
// host's monotonic clock, from each data packet's device time and host arrival time. The same
// algorithm step for step as the C, Python and Rust runtimes (the corpus tests/clock/cases.txt).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "protopkg/framing.hpp"

namespace protopkg {

class ClockModel {
  public:
    // the parameters: the spec's time.clock_model (framing.hpp)
    static constexpr std::int64_t kBucketNs = kClockBucketNs;    ///< device time per bucket
    static constexpr std::size_t kBuckets = kClockBuckets;       ///< closed buckets kept
    static constexpr std::size_t kMinBuckets = kClockMinBuckets; ///< closed buckets before an estimate
    static constexpr std::int64_t kRestartNs = kClockRestartNs;  ///< a larger step disagreement restarts

    /// One data packet: its device reference time and host arrival time (ns); its host time once
    /// estimated.
    std::optional<std::int64_t> add(std::int64_t device_ns, std::int64_t host_ns) {
        if (count_ > 0) {
            std::int64_t step = (host_ns - last_a_) - (device_ns - last_d_);
            if (device_ns < last_d_ || step > kRestartNs || step < -kRestartNs) {
                std::uint32_t restarts = restarts_;
                *this = ClockModel();
                restarts_ = restarts + 1;
            }
        }
        if (count_ == 0) {
            d0_ = device_ns;
            a0_ = host_ns;
        }
        std::int64_t x = device_ns - d0_;
        std::int64_t y = (host_ns - a0_) - x;
        std::int64_t b = x / kBucketNs;
        if (count_ == 0) {
            bucket_ = b;
            cur_x_ = x;
            cur_y_ = y;
        } else if (b != bucket_) {
            close_bucket();
            bucket_ = b;
            cur_x_ = x;
            cur_y_ = y;
        } else if (y < cur_y_) {
            cur_x_ = x;
            cur_y_ = y;
        }
        count_++;
        last_d_ = device_ns;
        last_a_ = host_ns;
        return host_time(device_ns);
    }

    bool estimated() const {
        return estimated_;
    }
    /// Discontinuities seen (device time went back, or a jump).
    std::uint32_t restarts() const {
        return restarts_;
    }
    /// The largest residual of a kept point above the fitted line (ns, rounded up).
    std::int64_t bound_ns() const {
        return bound_ns_;
    }

    /// The host time of device time device_ns; nothing until estimated.
    std::optional<std::int64_t> host_time(std::int64_t device_ns) const {
        if (!estimated_) {
            return std::nullopt;
        }
        std::int64_t x = device_ns - d0_;
        return a0_ + x + fy_ + floor_i64(slope_ * static_cast<double>(x - fx_) + 0.5);
    }
    /// How fast the device's reference clock runs against the host's, in ppm (positive: faster).
    std::optional<double> drift_ppm() const {
        if (!estimated_) {
            return std::nullopt;
        }
        return -1e6 * slope_ / (1.0 + slope_);
    }
    /// Host time minus device time at the latest packet.
    std::optional<std::int64_t> offset_ns() const {
        auto h = host_time(last_d_);
        if (!h) {
            return std::nullopt;
        }
        return *h - last_d_;
    }

  private:
    // a * b > c * d, exactly (two's complement 128-bit products from 32-bit halves; no 128-bit type).
    static void mul128(std::int64_t a, std::int64_t b, std::uint64_t &hi, std::uint64_t &lo) {
        std::uint64_t ua = a < 0 ? 0 - static_cast<std::uint64_t>(a) : static_cast<std::uint64_t>(a);
        std::uint64_t ub = b < 0 ? 0 - static_cast<std::uint64_t>(b) : static_cast<std::uint64_t>(b);
        std::uint64_t a0 = ua & 0xFFFFFFFFu, a1 = ua >> 32, b0 = ub & 0xFFFFFFFFu, b1 = ub >> 32;
        std::uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
        std::uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
        lo = (p00 & 0xFFFFFFFFu) | (mid << 32);
        hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
        if ((a < 0) != (b < 0)) {
            lo = ~lo + 1;
            hi = ~hi + (lo == 0 ? 1u : 0u);
        }
    }
    static bool product_greater(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) {
        std::uint64_t h1, l1, h2, l2;
        mul128(a, b, h1, l1);
        mul128(c, d, h2, l2);
        h1 ^= std::uint64_t{1} << 63;
        h2 ^= std::uint64_t{1} << 63;
        return h1 > h2 || (h1 == h2 && l1 > l2);
    }
    static std::int64_t floor_i64(double v) {
        auto t = static_cast<std::int64_t>(v);
        return static_cast<double>(t) > v ? t - 1 : t;
    }

    void close_bucket() {
        if (kept_ == kBuckets) {
            head_ = (head_ + 1) % kBuckets;
            kept_--;
        }
        std::size_t at = (head_ + kept_) % kBuckets;
        xs_[at] = cur_x_;
        ys_[at] = cur_y_;
        kept_++;
        if (kept_ >= kMinBuckets) {
            fit();
        }
    }

    void fit() {
        std::array<std::int64_t, kBuckets> xs{}, ys{};
        std::array<std::size_t, kBuckets> hull{};
        std::size_t n = kept_, h = 0, i = 0;
        std::int64_t sum_x = 0;
        for (std::size_t k = 0; k < n; k++) {
            xs[k] = xs_[(head_ + k) % kBuckets];
            ys[k] = ys_[(head_ + k) % kBuckets];
            sum_x += xs[k];
        }
        for (std::size_t k = 0; k < n; k++) { // the lower convex hull, by increasing x
            while (h >= 2) {
                std::size_t o = hull[h - 2], p = hull[h - 1];
                // p is dropped when it is on or above the line from o to k
                if (product_greater(xs[p] - xs[o], ys[k] - ys[o], ys[p] - ys[o], xs[k] - xs[o])) {
                    break;
                }
                h--;
            }
            hull[h++] = k;
        }
        while (xs[hull[i + 1]] * static_cast<std::int64_t>(n) < sum_x) { // the edge spanning the mean x
            i++;
        }
        fx_ = xs[hull[i]];
        fy_ = ys[hull[i]];
        slope_ = static_cast<double>(ys[hull[i + 1]] - fy_) / static_cast<double>(xs[hull[i + 1]] - fx_);
        double worst = 0.0;
        for (std::size_t k = 0; k < n; k++) {
            double r = static_cast<double>(ys[k] - fy_) - slope_ * static_cast<double>(xs[k] - fx_);
            worst = r > worst ? r : worst;
        }
        bound_ns_ = -floor_i64(-worst);
        estimated_ = true;
    }

    std::array<std::int64_t, kBuckets> xs_{}; // kept points: device time - d0
    std::array<std::int64_t, kBuckets> ys_{}; // (arrival - a0) - (device time - d0)
    std::size_t head_ = 0, kept_ = 0;
    std::uint64_t count_ = 0;
    std::uint32_t restarts_ = 0;
    std::int64_t d0_ = 0, a0_ = 0, last_d_ = 0, last_a_ = 0, bucket_ = 0, cur_x_ = 0, cur_y_ = 0;
    bool estimated_ = false;
    std::int64_t fx_ = 0, fy_ = 0, bound_ns_ = 0;
    double slope_ = 0.0;
};

} // namespace protopkg
