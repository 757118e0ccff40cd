/work/wt-robustapi/generator/targets/rust/runtime/target/debug/deps/protocodec-c380851aa63f5065.d: harness/lib.rs harness/../src/bounded.rs harness/../src/builder.rs harness/dispatch.rs harness/../src/error.rs harness/../src/fields.rs harness/framing.rs harness/../src/json.rs harness/../src/json_read.rs harness/../src/parser.rs harness/../src/samples.rs harness/../src/text.rs harness/../src/wire.rs harness/../src/framing_checksum.rs

/work/wt-robustapi/generator/targets/rust/runtime/target/debug/deps/libprotocodec-c380851aa63f5065.rlib: harness/lib.rs harness/../src/bounded.rs harness/../src/builder.rs harness/dispatch.rs harness/../src/error.rs harness/../src/fields.rs harness/framing.rs harness/../src/json.rs harness/../src/json_read.rs harness/../src/parser.rs harness/../src/samples.rs harness/../src/text.rs harness/../src/wire.rs harness/../src/framing_checksum.rs

/work/wt-robustapi/generator/targets/rust/runtime/target/debug/deps/libprotocodec-c380851aa63f5065.rmeta: harness/lib.rs harness/../src/bounded.rs harness/../src/builder.rs harness/dispatch.rs harness/../src/error.rs harness/../src/fields.rs harness/framing.rs harness/../src/json.rs harness/../src/json_read.rs harness/../src/parser.rs harness/../src/samples.rs harness/../src/text.rs harness/../src/wire.rs harness/../src/framing_checksum.rs

harness/lib.rs:
harness/../src/bounded.rs:
harness/../src/builder.rs:
harness/dispatch.rs:
harness/../src/error.rs:
harness/../src/fields.rs:
harness/framing.rs:
harness/../src/json.rs:
harness/../src/json_read.rs:
harness/../src/parser.rs:
harness/../src/samples.rs:
harness/../src/text.rs:
harness/../src/wire.rs:
harness/../src/framing_checksum.rs:
