//! The runtime of the generated Rust codecs (`src/`, copied verbatim into every crate), built
//! here against a tiny hand-written protocol: `harness/framing.rs` stands in for the generated
//! constants module and `harness/dispatch.rs` for the generated field dispatch. The module tree
//! is that of a generated crate (templates/rust/lib.rs.j2), without the per-set modules.
#![cfg_attr(not(feature = "std"), no_std)]
#![forbid(unsafe_code)]

#[path = "../src/bounded.rs"]
pub mod bounded;
#[path = "../src/builder.rs"]
pub mod builder;
pub mod commands;
#[cfg(feature = "std")]
#[path = "../src/device.rs"]
pub mod device;
pub mod dispatch;
#[path = "../src/error.rs"]
pub mod error;
#[path = "../src/fields.rs"]
pub mod fields;
pub mod framing;
#[path = "../src/json.rs"]
pub mod json;
#[cfg(feature = "std")]
#[path = "../src/json_read.rs"]
pub mod json_read;
#[path = "../src/parser.rs"]
pub mod parser;
#[path = "../src/samples.rs"]
pub mod samples;
#[path = "../src/session.rs"]
pub mod session;
#[cfg(feature = "std")]
#[path = "../src/text.rs"]
pub mod text;
#[path = "../src/wire.rs"]
pub mod wire;

pub use dispatch::{decode_field, Device, FieldValue};
pub use error::{DecodeError, EncodeError};
