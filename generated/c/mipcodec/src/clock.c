/* The host clock model (docs/time.md); the same algorithm step for step as the other runtimes
 * (Python clock.py, C++ clock.hpp, Rust clock.rs), which run the same corpus tests/clock/cases.txt.
 * Generated: do not edit. */
#include "mipcodec/clock.h"

#include <assert.h>
#include <string.h>

static void restart(mipc_clock_t *c) {
    uint32_t restarts = c->restarts;
    memset(c, 0, sizeof *c);
    c->restarts = restarts;
}

void mipc_clock_init(mipc_clock_t *clock) {
    assert(clock != NULL);
    memset(clock, 0, sizeof *clock);
}

/* a * b as a two's complement 128-bit number (hi, lo): exact, with no 128-bit type (C99, 32-bit targets). */
static void mul128(int64_t a, int64_t b, uint64_t *hi, uint64_t *lo) {
    uint64_t ua = a < 0 ? 0 - (uint64_t)a : (uint64_t)a;
    uint64_t ub = b < 0 ? 0 - (uint64_t)b : (uint64_t)b;
    uint64_t a0 = ua & 0xFFFFFFFFu, a1 = ua >> 32, b0 = ub & 0xFFFFFFFFu, b1 = ub >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
    *lo = (p00 & 0xFFFFFFFFu) | (mid << 32);
    *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    if ((a < 0) != (b < 0)) {
        *lo = ~*lo + 1;
        *hi = ~*hi + (*lo == 0 ? 1u : 0u);
    }
}

/* a * b > c * d, exactly. */
static bool product_greater(int64_t a, int64_t b, int64_t c, int64_t d) {
    uint64_t h1, l1, h2, l2;
    mul128(a, b, &h1, &l1);
    mul128(c, d, &h2, &l2);
    h1 ^= (uint64_t)1 << 63; /* signed order as unsigned order */
    h2 ^= (uint64_t)1 << 63;
    return h1 > h2 || (h1 == h2 && l1 > l2);
}

/* floor(v) for |v| < 2^62, without libm (the same value as Python's math.floor). */
static int64_t floor_i64(double v) {
    int64_t t = (int64_t)v;
    return (double)t > v ? t - 1 : t;
}

static void fit(mipc_clock_t *c) {
    int64_t xs[MIPC_CLOCK_BUCKETS], ys[MIPC_CLOCK_BUCKETS];
    uint32_t hull[MIPC_CLOCK_BUCKETS];
    uint32_t n = c->kept, h = 0, k, i = 0;
    int64_t sum_x = 0;
    double worst = 0.0;
    for (k = 0; k < n; k++) {
        xs[k] = c->xs[(c->head + k) % MIPC_CLOCK_BUCKETS];
        ys[k] = c->ys[(c->head + k) % MIPC_CLOCK_BUCKETS];
        sum_x += xs[k];
    }
    for (k = 0; k < n; k++) { /* the lower convex hull, by increasing x */
        while (h >= 2) {
            uint32_t o = hull[h - 2], p = hull[h - 1];
            /* p is dropped when it is on or above the line from o to k */
            if (product_greater(xs[p] - xs[o], ys[k] - ys[o], ys[p] - ys[o], xs[k] - xs[o])) {
                break;
            }
            h--;
        }
        hull[h++] = k;
    }
    while (xs[hull[i + 1]] * (int64_t)n < sum_x) { /* the edge spanning the mean x */
        i++;
    }
    c->fx = xs[hull[i]];
    c->fy = ys[hull[i]];
    c->slope = (double)(ys[hull[i + 1]] - c->fy) / (double)(xs[hull[i + 1]] - c->fx);
    for (k = 0; k < n; k++) {
        double r = (double)(ys[k] - c->fy) - c->slope * (double)(xs[k] - c->fx);
        worst = r > worst ? r : worst;
    }
    c->bound_ns = -floor_i64(-worst); /* ceil */
    c->estimated = true;
}

static void close_bucket(mipc_clock_t *c) {
    uint32_t at;
    if (c->kept == MIPC_CLOCK_BUCKETS) {
        c->head = (c->head + 1) % MIPC_CLOCK_BUCKETS;
        c->kept--;
    }
    at = (c->head + c->kept) % MIPC_CLOCK_BUCKETS;
    c->xs[at] = c->cur_x;
    c->ys[at] = c->cur_y;
    c->kept++;
    if (c->kept >= MIPC_CLOCK_MIN_BUCKETS) {
        fit(c);
    }
}

bool mipc_clock_add(mipc_clock_t *c, int64_t d, int64_t a, int64_t *host_out) {
    int64_t x, y, b;
    assert(c != NULL);
    if (c->count > 0) {
        int64_t step = (a - c->last_a) - (d - c->last_d);
        if (d < c->last_d || step > MIPC_CLOCK_RESTART_NS || step < -MIPC_CLOCK_RESTART_NS) {
            restart(c);
            c->restarts++;
        }
    }
    if (c->count == 0) {
        c->d0 = d;
        c->a0 = a;
    }
    x = d - c->d0;
    y = (a - c->a0) - x;
    b = x / MIPC_CLOCK_BUCKET_NS; /* x >= 0 */
    if (c->count == 0) {
        c->bucket = b;
        c->cur_x = x;
        c->cur_y = y;
    } else if (b != c->bucket) {
        close_bucket(c);
        c->bucket = b;
        c->cur_x = x;
        c->cur_y = y;
    } else if (y < c->cur_y) {
        c->cur_x = x;
        c->cur_y = y;
    }
    c->count++;
    c->last_d = d;
    c->last_a = a;
    if (!c->estimated) {
        return false;
    }
    return host_out == NULL || mipc_clock_host_time(c, d, host_out);
}

bool mipc_clock_host_time(const mipc_clock_t *c, int64_t device_ns, int64_t *host_out) {
    int64_t x;
    assert(c != NULL && host_out != NULL);
    if (!c->estimated) {
        return false;
    }
    x = device_ns - c->d0;
    *host_out = c->a0 + x + c->fy + floor_i64(c->slope * (double)(x - c->fx) + 0.5);
    return true;
}

double mipc_clock_drift_ppm(const mipc_clock_t *c) {
    assert(c != NULL);
    return c->estimated ? -1e6 * c->slope / (1.0 + c->slope) : 0.0;
}

int64_t mipc_clock_offset_ns(const mipc_clock_t *c) {
    int64_t host = 0;
    assert(c != NULL);
    return mipc_clock_host_time(c, c->last_d, &host) ? host - c->last_d : 0;
}
