//! Nothing: the runtime's tests are the integration tests of this crate (Cargo.toml), against
//! the rendered test protocol (its `protocodec` dependency).
#![forbid(unsafe_code)]
