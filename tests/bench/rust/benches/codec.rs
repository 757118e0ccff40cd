//! Criterion benchmark of the same work as the plain runner (`src/main.rs`): frame and decode
//! over each benchmark stream, with criterion's statistics and throughput in bytes.
//!   CARGO_TARGET_DIR=build/bench/rust cargo bench --manifest-path tests/bench/rust/Cargo.toml
//! The stream directory is $MIP_BENCH_DIR (default: build/bench of the repository); write it with
//! `python tests/bench/streams.py` first. Counts are checked against the sidecars before timing.

use std::hint::black_box;
use std::path::PathBuf;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use mipcodec_bench::{decode, frame, Stream, STREAMS};

fn stream_dir() -> PathBuf {
    match std::env::var_os("MIP_BENCH_DIR") {
        Some(d) => PathBuf::from(d),
        None => PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../build/bench"),
    }
}

fn bench(c: &mut Criterion) {
    let dir = stream_dir();
    for name in STREAMS {
        let stream = Stream::load(&dir, name)
            .unwrap_or_else(|e| panic!("{e} (run tests/bench/streams.py first)"));
        frame(&stream.data).check(&stream, false).unwrap();
        decode(&stream.data).check(&stream, true).unwrap();
        let mut group = c.benchmark_group(name);
        group.throughput(Throughput::Elements(stream.packets));
        group.sample_size(10);
        group.bench_function("frame", |b| b.iter(|| frame(black_box(&stream.data))));
        group.bench_function("decode", |b| b.iter(|| decode(black_box(&stream.data))));
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
