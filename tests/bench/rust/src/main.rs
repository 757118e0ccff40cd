//! Plain benchmark runner: `mipcodec-bench DIR [PASSES [STREAM...]]` loads the streams of DIR
//! (written by `tests/bench/streams.py`; all four unless STREAMs are named), checks the counts
//! of every pass against the sidecars and prints one line per stream and mode for
//! `tests/bench/run.py`:
//!   BENCH lang=rust stream=NAME mode=frame|decode packets=N bytes=B seconds=BEST
//! where BEST is the fastest of PASSES (default 5) passes over the in-memory stream.
//! Exits non-zero if a stream is missing or a count does not match.

use std::hint::black_box;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use mipcodec_bench::{decode, frame, Stream, Tally, STREAMS};

fn best_of(
    passes: u32,
    stream: &Stream,
    work: fn(&[u8]) -> Tally,
    decode: bool,
) -> Result<(f64, Tally), String> {
    let mut best = f64::INFINITY;
    let mut last = Tally::default();
    for _ in 0..passes {
        let start = Instant::now();
        let t = work(black_box(&stream.data));
        let secs = start.elapsed().as_secs_f64();
        t.check(stream, decode)?;
        best = best.min(secs);
        last = t;
    }
    Ok((best, last))
}

fn run() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let dir = PathBuf::from(
        args.next()
            .ok_or("usage: mipcodec-bench DIR [PASSES [STREAM...]]")?,
    );
    let passes: u32 = match args.next() {
        Some(p) => p
            .parse()
            .map_err(|_| format!("PASSES must be a number, got {p}"))?,
        None => 5,
    };
    let only: Vec<String> = args.collect();
    if let Some(bad) = only.iter().find(|n| !STREAMS.contains(&n.as_str())) {
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
        for (mode, work, is_decode) in [
            ("frame", frame as fn(&[u8]) -> Tally, false),
            ("decode", decode, true),
        ] {
            let (secs, t) = best_of(passes, &stream, work, is_decode)?;
            println!(
                "BENCH lang=rust stream={name} mode={mode} packets={} bytes={} seconds={secs:.6}",
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
