/work/wt-robustapi/generator/targets/rust/runtime/target/debug/deps/protocodec_decode-5ec1cd12e00857d2.d: src/bin/protocodec-decode.rs

/work/wt-robustapi/generator/targets/rust/runtime/target/debug/deps/protocodec_decode-5ec1cd12e00857d2: src/bin/protocodec-decode.rs

src/bin/protocodec-decode.rs:
