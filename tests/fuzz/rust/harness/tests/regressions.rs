//! Replays tests/fuzz/regressions/<package>/<target>/* (inputs that once failed a harness in
//! some language) through the Rust harnesses, as plain tests (no libFuzzer needed), and, when
//! FUZZ_SEED_CORPUS names a seed directory (tests/fuzz/seeds.py output), the seeds too.

use std::path::{Path, PathBuf};

fn files_in(dir: &Path) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = match std::fs::read_dir(dir) {
        Ok(entries) => entries
            .map(|e| e.expect("directory entry").path())
            .filter(|p| {
                p.is_file()
                    && !p
                        .file_name()
                        .is_some_and(|n| n.to_string_lossy().starts_with('.'))
            })
            .collect(),
        Err(_) => Vec::new(),
    };
    files.sort();
    files
}

fn inputs(package: &str, target: &str) -> Vec<PathBuf> {
    let mut files = files_in(
        &Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../regressions")
            .join(package)
            .join(target),
    );
    if let Some(corpus) = std::env::var_os("FUZZ_SEED_CORPUS") {
        let seeds = files_in(&Path::new(&corpus).join(package).join(target));
        assert!(
            !seeds.is_empty(),
            "no seeds for {package}/{target} in FUZZ_SEED_CORPUS"
        );
        files.extend(seeds);
    }
    files
}

fn replay(package: &str, target: &str, run: fn(&[u8])) {
    let files = inputs(package, target);
    for path in &files {
        eprintln!("replay: {}", path.display());
        run(&std::fs::read(path).expect("readable input"));
    }
    eprintln!("replay: {package}/{target}: {} inputs passed", files.len());
}

#[test]
fn mipcodec_parser() {
    // A ping (the README example) with one garbage byte before it, fed one byte at a time.
    fuzz_harness::mipcodec::parser(&[0x00, 0x00, 0x75, 0x65, 0x01, 0x02, 0x02, 0x01, 0xe0, 0xc6]);
    replay("mipcodec", "parser", fuzz_harness::mipcodec::parser);
}

#[test]
fn mipcodec_json() {
    fuzz_harness::mipcodec::json(
        br#"{"offset":1,"set":1,"fields":[{"descriptor":1,"name":"ping","values":{}}]}"#,
    );
    replay("mipcodec", "json", fuzz_harness::mipcodec::json);
}

#[test]
fn mscipcodec_parser() {
    // Select Sensors Rev A (the README example): size byte one less than its data.
    fuzz_harness::mscipcodec::parser(&[
        0x05, 0xa5, 0xa5, 0x02, 0x06, 0x05, 0x03, 0x01, 0x00, 0x81, 0x82, 0x5e, 0x2e,
    ]);
    replay("mscipcodec", "parser", fuzz_harness::mscipcodec::parser);
}

#[test]
fn mscipcodec_json() {
    fuzz_harness::mscipcodec::json(br#"{"offset":0,"skipped":"a5a5"}"#);
    replay("mscipcodec", "json", fuzz_harness::mscipcodec::json);
}

#[test]
fn mipcodec_decode() {
    fuzz_harness::mipcodec::decode(&[0x00, 0x00, 0x75, 0x65, 0x01, 0x02, 0x02, 0x01, 0xe0, 0xc6]);
    replay("mipcodec", "decode", fuzz_harness::mipcodec::decode);
}

#[test]
fn mscipcodec_decode() {
    fuzz_harness::mscipcodec::decode(&[
        0x05, 0xa5, 0xa5, 0x02, 0x06, 0x05, 0x03, 0x01, 0x00, 0x81, 0x82, 0x5e, 0x2e,
    ]);
    replay("mscipcodec", "decode", fuzz_harness::mscipcodec::decode);
}
