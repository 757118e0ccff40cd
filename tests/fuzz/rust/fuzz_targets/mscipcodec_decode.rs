//! cargo-fuzz target: fuzz_harness::mscipcodec::decode (see harness/src/lib.rs for what it checks).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| fuzz_harness::mscipcodec::decode(data));
