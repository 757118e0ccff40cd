/* The host clock model (docs/time.md): offset and drift of a device's reference clock against the
 * host's monotonic clock, from each data packet's device time and host arrival time. */
/*
 * Pointer arguments: a pointer must be valid and not NULL, unless its documentation says "may be
 * NULL". Debug builds (without NDEBUG) check this with assert(); docs/conformance.md section 7.
 */
#ifndef CODEC_CLOCK_H
#define CODEC_CLOCK_H

#include <stdbool.h>
#include <stdint.h>

#include "codec/protocol.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The model's parameters come from codec/protocol.h (the spec's time.clock_model):
 * CODEC_CLOCK_BUCKET_NS (device time per bucket), CODEC_CLOCK_BUCKETS (closed buckets kept),
 * CODEC_CLOCK_MIN_BUCKETS (closed buckets before there is an estimate), CODEC_CLOCK_RESTART_NS (a
 * larger step disagreement restarts the model). */

/**
 * Fixed-size state (no allocation; about 1.2 KB). Per bucket of device time the packet with the
 * smallest arrival - device time, the last CODEC_CLOCK_BUCKETS closed buckets, and the line fitted
 * under them when a bucket closed. Read the estimate with the functions below.
 */
typedef struct {
    int64_t xs[CODEC_CLOCK_BUCKETS]; /* kept points: device time - d0 */
    int64_t ys[CODEC_CLOCK_BUCKETS]; /* (arrival - a0) - (device time - d0) */
    uint32_t head, kept;             /* ring: oldest point at head, kept points */
    uint64_t count;                  /* packets since the last restart */
    uint32_t restarts;               /* discontinuities seen (device time back, or a jump) */
    int64_t d0, a0, last_d, last_a, bucket, cur_x, cur_y;
    bool estimated;
    int64_t fx, fy; /* the line: y = fy + slope * (x - fx) */
    double slope;
    int64_t bound_ns; /* the largest residual of a kept point above the line, rounded up */
} codec_clock_t;

void codec_clock_init(codec_clock_t *clock);
/**
 * One data packet: its device reference time and host arrival time (ns). Returns true and sets
 * *host_ns (may be NULL) to the packet's host time once estimated; false before.
 */
bool codec_clock_add(codec_clock_t *clock, int64_t device_ns, int64_t host_ns, int64_t *host_out);
/** The host time of device time device_ns into *host_out; false (nothing written) until estimated. */
bool codec_clock_host_time(const codec_clock_t *clock, int64_t device_ns, int64_t *host_out);
/** How fast the device's reference clock runs against the host's, in ppm (positive: faster); 0 until
 * estimated. */
double codec_clock_drift_ppm(const codec_clock_t *clock);
/** Host time minus device time at the latest packet; 0 until estimated. */
int64_t codec_clock_offset_ns(const codec_clock_t *clock);

#ifdef __cplusplus
}
#endif

#endif
