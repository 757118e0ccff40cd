//! Plain benchmark runner: `mipcodec-bench DIR [PASSES [STREAM...]] [--mode MODE]` loads the
//! streams of DIR (written by `tests/bench/streams.py`; all four unless STREAMs are named), checks
//! the counts of every pass against the sidecars and prints one line per stream and mode for
//! `tests/bench/run.py`:
//!   BENCH lang=rust stream=NAME mode=bulk|frame|decode|decode-cached|decode-straight|session-ingest packets=N bytes=B seconds=BEST
//! where BEST is the fastest of PASSES (default 5) passes over the in-memory stream (mode bulk:
//! one memcpy of the whole stream into another buffer, written once before timing: the limit
//! the parsers' rows are divided by), then
//!   BENCH lang=rust stream=loopback-tcp mode=session-roundtrip packets=N bytes=B seconds=BEST
//! for N ping round trips through the blocking session API over loopback TCP.
//! `--mode MODE` runs that mode only (`none`: nothing, no line; with a STREAM named, the program's
//! fixed cost that instruction counts subtract, `tests/bench/run.py --instructions`).
//! Exits non-zero if a stream is missing or a count does not match.

use std::hint::black_box;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use mipcodec_bench::{
    decode, decode_field_each, decode_straight, frame, session_ingest, session_roundtrip, Stream,
    Tally, STREAMS,
};

/// Ping round trips of one session-roundtrip pass.
const ROUND_TRIPS: u64 = 2000;

/// The CPU time of this thread in seconds (clock_gettime CLOCK_THREAD_CPUTIME_ID): what a pass
/// costs, without the scheduler ticks other tasks take on a shared machine (docs/benchmarks.md).
#[cfg(all(target_os = "linux", target_pointer_width = "64"))]
fn cpu_now() -> f64 {
    #[repr(C)]
    struct Timespec {
        tv_sec: i64,
        tv_nsec: i64,
    }
    extern "C" {
        fn clock_gettime(clock: i32, ts: *mut Timespec) -> i32;
    }
    const CLOCK_THREAD_CPUTIME_ID: i32 = 3;
    let mut ts = Timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime writes one timespec (two 64-bit fields on 64-bit Linux) to `ts`.
    let rc = unsafe { clock_gettime(CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    assert_eq!(rc, 0, "clock_gettime(CLOCK_THREAD_CPUTIME_ID)");
    ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
}

/// Elsewhere: the wall clock since the first call.
#[cfg(not(all(target_os = "linux", target_pointer_width = "64")))]
fn cpu_now() -> f64 {
    thread_local!(static START: Instant = Instant::now());
    START.with(|s| s.elapsed().as_secs_f64())
}

fn best_of(
    passes: u32,
    stream: &Stream,
    work: fn(&[u8]) -> Tally,
    decode: bool,
) -> Result<(f64, Tally), String> {
    let mut best = f64::INFINITY;
    let mut last = Tally::default();
    for _ in 0..passes {
        let start = cpu_now();
        let t = work(black_box(&stream.data));
        let secs = cpu_now() - start;
        t.check(stream, decode)?;
        best = best.min(secs);
        last = t;
    }
    Ok((best, last))
}

/// Best time of `passes` copies of the whole stream into `into` (one memcpy each).
fn bulk(passes: u32, stream: &Stream, into: &mut [u8]) -> Result<f64, String> {
    let mut best = f64::INFINITY;
    for _ in 0..passes {
        let start = cpu_now();
        black_box(&mut *into).copy_from_slice(black_box(&stream.data));
        black_box(&*into);
        best = best.min(cpu_now() - start);
    }
    if into != stream.data.as_slice() {
        return Err(format!(
            "{}: bulk: the copy differs from the stream",
            stream.name
        ));
    }
    Ok(best)
}

const MODES: [&str; 8] = [
    "bulk",
    "frame",
    "decode",
    "decode-cached",
    "decode-straight",
    "session-ingest",
    "session-roundtrip",
    "none",
];

fn run() -> Result<(), String> {
    let mut all: Vec<String> = std::env::args().skip(1).collect();
    let mut mode_only: Option<String> = None;
    if let Some(at) = all.iter().position(|a| a == "--mode") {
        if at + 1 >= all.len() {
            return Err("--mode needs a value".into());
        }
        let m = all.remove(at + 1);
        all.remove(at);
        if !MODES.contains(&m.as_str()) {
            return Err(format!("unknown mode {m} (modes: {})", MODES.join(", ")));
        }
        mode_only = Some(m);
    }
    let wants = |m: &str| mode_only.as_deref().is_none_or(|o| o == m);
    let mut args = all.into_iter();
    let dir = PathBuf::from(
        args.next()
            .ok_or("usage: mipcodec-bench DIR [PASSES [STREAM...]] [--mode MODE]")?,
    );
    let passes: u32 = match args.next() {
        Some(p) => p
            .parse()
            .map_err(|_| format!("PASSES must be a number, got {p}"))?,
        None => 5,
    };
    let only: Vec<String> = args.collect();
    if let Some(bad) = only
        .iter()
        .find(|n| !STREAMS.contains(&n.as_str()) && n.as_str() != "loopback-tcp")
    {
        return Err(format!(
            "unknown stream {bad} (streams: {})",
            STREAMS.join(", ")
        ));
    }
    if passes == 0 {
        return Err("PASSES must be at least 1".into());
    }
    for name in STREAMS {
        if !only.is_empty() && !only.iter().any(|n| n == name) {
            continue;
        }
        let stream = Stream::load(&dir, name)?;
        if wants("bulk") {
            let mut into = vec![0u8; stream.data.len()];
            let secs = bulk(passes, &stream, &mut into)?;
            println!(
                "BENCH lang=rust stream={name} mode=bulk packets={} bytes={} seconds={secs:.9}",
                stream.packets,
                stream.data.len()
            );
        }
        for (mode, work, is_decode) in [
            ("frame", frame as fn(&[u8]) -> Tally, false),
            ("decode", decode_field_each, true),
            ("decode-cached", decode, true),
            ("decode-straight", decode_straight, true),
            ("session-ingest", session_ingest, true),
        ] {
            if !wants(mode) {
                continue;
            }
            let (secs, t) = best_of(passes, &stream, work, is_decode)?;
            println!(
                "BENCH lang=rust stream={name} mode={mode} packets={} bytes={} seconds={secs:.9}",
                t.packets,
                stream.data.len()
            );
            eprintln!(
                "rust {name:<19} {mode:<6} {:7.2} Mpkt/s {:8.1} MB/s  (checksum {})",
                t.packets as f64 / secs / 1e6,
                stream.data.len() as f64 / secs / 1e6,
                t.checksum
            );
        }
    }
    if wants("session-roundtrip") && (only.is_empty() || only.iter().any(|n| n == "loopback-tcp")) {
        let mut best = f64::INFINITY;
        let mut bytes = 0;
        for _ in 0..passes {
            let start = Instant::now();
            bytes = session_roundtrip(ROUND_TRIPS)?;
            best = best.min(start.elapsed().as_secs_f64());
        }
        println!(
            "BENCH lang=rust stream=loopback-tcp mode=session-roundtrip packets={ROUND_TRIPS} bytes={bytes} seconds={best:.6}"
        );
        eprintln!(
            "rust loopback-tcp session-roundtrip {:8.1} us per round trip",
            best / ROUND_TRIPS as f64 * 1e6
        );
    }
    Ok(())
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("mipcodec-bench: {e}");
            ExitCode::FAILURE
        }
    }
}
