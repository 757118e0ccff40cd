/work/wt-robustapi/generator/targets/rust/runtime/target/debug/deps/protocodec_encode-ccc51e6e6db48cde.d: src/bin/protocodec-encode.rs

/work/wt-robustapi/generator/targets/rust/runtime/target/debug/deps/protocodec_encode-ccc51e6e6db48cde: src/bin/protocodec-encode.rs

src/bin/protocodec-encode.rs:
