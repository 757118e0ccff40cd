//! The host clock model (docs/time.md): offset and drift of a device's reference clock against the
//! host's monotonic clock, from each data packet's device time and host arrival time.
//!
//! A packet never arrives before it was sent, so the model estimates the lower envelope of the
//! arrival times: per bucket of device time ([`BUCKET_NS`]) it keeps the packet with the smallest
//! arrival - device time, keeps the last [`BUCKETS`] buckets, and when a bucket closes fits the line
//! under every kept point that is highest at their mean device time (the lower convex hull's edge
//! spanning the mean). The hull is exact integer arithmetic; only the slope and what uses it are
//! `f64`. The same algorithm step for step as the C, C++ and Python runtimes (the corpus
//! tests/clock/cases.txt). `no_std`, no allocation.

// The parameters: the spec's time.clock_model (the project's own choice), generated into
// crate::framing.
/// Device time per bucket (ns).
pub const BUCKET_NS: i64 = crate::framing::CLOCK_BUCKET_NS;
/// Closed buckets kept.
pub const BUCKETS: usize = crate::framing::CLOCK_BUCKETS;
/// Closed buckets before there is an estimate.
pub const MIN_BUCKETS: usize = crate::framing::CLOCK_MIN_BUCKETS;
/// Consecutive packets whose arrival and device time steps differ by more restart the model.
pub const RESTART_NS: i64 = crate::framing::CLOCK_RESTART_NS;

/// Offset and drift of a device's reference clock against the host's (fixed size, about 1.2 KB).
#[derive(Clone, Debug)]
pub struct ClockModel {
    xs: [i64; BUCKETS], // kept points: device time - d0
    ys: [i64; BUCKETS], // (arrival - a0) - (device time - d0)
    head: usize,
    kept: usize,
    count: u64,
    restarts: u32,
    d0: i64,
    a0: i64,
    last_d: i64,
    last_a: i64,
    bucket: i64,
    cur_x: i64,
    cur_y: i64,
    estimated: bool,
    fx: i64,
    fy: i64,
    slope: f64,
    bound_ns: i64,
}

impl Default for ClockModel {
    fn default() -> Self {
        Self::new()
    }
}

/// floor(v) for |v| < 2^62, without the standard library (the same value as C's and Python's).
fn floor_i64(v: f64) -> i64 {
    let t = v as i64;
    if t as f64 > v {
        t - 1
    } else {
        t
    }
}

impl ClockModel {
    /// A model with no packets.
    pub const fn new() -> Self {
        ClockModel {
            xs: [0; BUCKETS],
            ys: [0; BUCKETS],
            head: 0,
            kept: 0,
            count: 0,
            restarts: 0,
            d0: 0,
            a0: 0,
            last_d: 0,
            last_a: 0,
            bucket: 0,
            cur_x: 0,
            cur_y: 0,
            estimated: false,
            fx: 0,
            fy: 0,
            slope: 0.0,
            bound_ns: 0,
        }
    }

    /// One data packet: its device reference time and host arrival time (ns); its host time once
    /// estimated.
    pub fn add(&mut self, device_ns: i64, host_ns: i64) -> Option<i64> {
        let (d, a) = (device_ns, host_ns);
        if self.count > 0 {
            let step = (a - self.last_a) - (d - self.last_d);
            if d < self.last_d || !(-RESTART_NS..=RESTART_NS).contains(&step) {
                let restarts = self.restarts;
                *self = ClockModel::new();
                self.restarts = restarts + 1;
            }
        }
        if self.count == 0 {
            self.d0 = d;
            self.a0 = a;
        }
        let x = d - self.d0;
        let y = (a - self.a0) - x;
        let b = x / BUCKET_NS;
        if self.count == 0 {
            self.bucket = b;
            self.cur_x = x;
            self.cur_y = y;
        } else if b != self.bucket {
            self.close_bucket();
            self.bucket = b;
            self.cur_x = x;
            self.cur_y = y;
        } else if y < self.cur_y {
            self.cur_x = x;
            self.cur_y = y;
        }
        self.count += 1;
        self.last_d = d;
        self.last_a = a;
        self.host_time(d)
    }

    /// True once there is an estimate.
    pub fn estimated(&self) -> bool {
        self.estimated
    }

    /// Discontinuities seen (device time went back, or a jump).
    pub fn restarts(&self) -> u32 {
        self.restarts
    }

    /// The largest residual of a kept point above the fitted line (ns, rounded up).
    pub fn bound_ns(&self) -> i64 {
        self.bound_ns
    }

    /// The host time of device time `device_ns`; `None` until estimated.
    pub fn host_time(&self, device_ns: i64) -> Option<i64> {
        if !self.estimated {
            return None;
        }
        let x = device_ns - self.d0;
        Some(self.a0 + x + self.fy + floor_i64(self.slope * (x - self.fx) as f64 + 0.5))
    }

    /// How fast the device's reference clock runs against the host's, in ppm (positive: faster).
    pub fn drift_ppm(&self) -> Option<f64> {
        if !self.estimated {
            return None;
        }
        Some(-1e6 * self.slope / (1.0 + self.slope))
    }

    /// Host time minus device time at the latest packet.
    pub fn offset_ns(&self) -> Option<i64> {
        self.host_time(self.last_d).map(|h| h - self.last_d)
    }

    fn close_bucket(&mut self) {
        if self.kept == BUCKETS {
            self.head = (self.head + 1) % BUCKETS;
            self.kept -= 1;
        }
        let at = (self.head + self.kept) % BUCKETS;
        self.xs[at] = self.cur_x;
        self.ys[at] = self.cur_y;
        self.kept += 1;
        if self.kept >= MIN_BUCKETS {
            self.fit();
        }
    }

    fn fit(&mut self) {
        let mut xs = [0i64; BUCKETS];
        let mut ys = [0i64; BUCKETS];
        let mut hull = [0usize; BUCKETS];
        let n = self.kept;
        let mut sum_x = 0i64;
        for k in 0..n {
            xs[k] = self.xs[(self.head + k) % BUCKETS];
            ys[k] = self.ys[(self.head + k) % BUCKETS];
            sum_x += xs[k];
        }
        let mut h = 0;
        for k in 0..n {
            // the lower convex hull, by increasing x
            while h >= 2 {
                let (o, p) = (hull[h - 2], hull[h - 1]);
                // p is dropped when it is on or above the line from o to k
                let left = i128::from(xs[p] - xs[o]) * i128::from(ys[k] - ys[o]);
                let right = i128::from(ys[p] - ys[o]) * i128::from(xs[k] - xs[o]);
                if left > right {
                    break;
                }
                h -= 1;
            }
            hull[h] = k;
            h += 1;
        }
        let mut i = 0;
        while xs[hull[i + 1]] * (n as i64) < sum_x {
            // the edge spanning the mean x
            i += 1;
        }
        self.fx = xs[hull[i]];
        self.fy = ys[hull[i]];
        self.slope = (ys[hull[i + 1]] - self.fy) as f64 / (xs[hull[i + 1]] - self.fx) as f64;
        let mut worst = 0.0f64;
        for k in 0..n {
            let r = (ys[k] - self.fy) as f64 - self.slope * (xs[k] - self.fx) as f64;
            if r > worst {
                worst = r;
            }
        }
        self.bound_ns = -floor_i64(-worst);
        self.estimated = true;
    }
}
