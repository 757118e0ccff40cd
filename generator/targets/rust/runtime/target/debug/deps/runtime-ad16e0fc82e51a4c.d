/work/wt-robustapi/generator/targets/rust/runtime/target/debug/deps/runtime-ad16e0fc82e51a4c.d: tests/runtime.rs

/work/wt-robustapi/generator/targets/rust/runtime/target/debug/deps/runtime-ad16e0fc82e51a4c: tests/runtime.rs

tests/runtime.rs:
