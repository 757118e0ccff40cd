#!/usr/bin/env bash
# Build, test and run the generated Rust crates.
#   tests/lang/rust.sh build                      cargo build --release of every crate under generated/rust/
#   tests/lang/rust.sh test                       the runtime in place (as `runtime`), then clippy
#                                                 -D warnings, cargo test, and a core-only
#                                                 (--no-default-features) build, for every crate
#   tests/lang/rust.sh runtime                    the runtime where it is edited, generator/targets/rust/
#                                                 runtime/ (no regeneration needed): rustfmt --check,
#                                                 clippy, rustdoc and cargo test
#   tests/lang/rust.sh decode FILE [--device ID]  run <package>-decode (FILE may be -)
#   tests/lang/rust.sh encode                     run <package>-encode (stdin -> stdout)
#   tests/lang/rust.sh example FILE               cargo run --example getting_started -- FILE
# The crate for decode/encode/example is $RUST_PACKAGE (default: mipcodec). Works from any directory.
# Target directories live under build/rust/ (never in generated/); cargo output goes to stderr.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
PACKAGE="${RUST_PACKAGE:-mipcodec}"
export CARGO_TARGET_DIR="$ROOT/build/rust/target"
# A separate target dir for the core-only build, so feature changes do not force rebuilds.
CORE_TARGET_DIR="$ROOT/build/rust/target-core"
# The runtime crate (hand-written, tested in place without a regeneration) and its target dir.
RUNTIME="$ROOT/generator/targets/rust/runtime"
RUNTIME_TARGET_DIR="$ROOT/build/rust/target-runtime"

usage() {
    echo "usage: tests/lang/rust.sh build | test | runtime | decode FILE [--device ID] | encode | example FILE" >&2
    exit 2
}

manifest() {
    echo "$ROOT/generated/rust/$1/Cargo.toml"
}

packages() {
    local d
    for d in "$ROOT"/generated/rust/*/; do
        [ -f "$d/Cargo.toml" ] && basename "$d"
    done
}

# The runtime where it is edited, against the tiny protocol of runtime/harness/: formatted as
# the generator formats what it copies, lint-free with and without std, and its unit tests.
test_runtime() {
    local m="$RUNTIME/Cargo.toml"
    echo "== runtime: rustfmt --check" >&2
    find "$RUNTIME" -name '*.rs' -print0 | xargs -0 rustfmt --check --edition 2021
    echo "== runtime: clippy" >&2
    CARGO_TARGET_DIR="$RUNTIME_TARGET_DIR" cargo clippy --quiet --manifest-path "$m" --all-targets -- -D warnings
    echo "== runtime: clippy (core only)" >&2
    CARGO_TARGET_DIR="$RUNTIME_TARGET_DIR" cargo clippy --quiet --manifest-path "$m" --lib --no-default-features -- -D warnings
    echo "== runtime: doc (warnings are errors)" >&2
    CARGO_TARGET_DIR="$RUNTIME_TARGET_DIR" RUSTDOCFLAGS="-D warnings" cargo doc --quiet --no-deps --manifest-path "$m"
    echo "== runtime: test" >&2
    CARGO_TARGET_DIR="$RUNTIME_TARGET_DIR" cargo test --quiet --manifest-path "$m"
}

build_one() {
    cargo build --release --quiet --manifest-path "$(manifest "$1")" --bins >&2
}

# Build the tools unless both exist and are newer than every file of the crate.
ensure_built() {
    local dec="$CARGO_TARGET_DIR/release/$PACKAGE-decode" enc="$CARGO_TARGET_DIR/release/$PACKAGE-encode"
    if [ -x "$dec" ] && [ -x "$enc" ] && [ -f "$(manifest "$PACKAGE")" ] \
        && [ -z "$(find "$ROOT/generated/rust/$PACKAGE" -type f \( -newer "$dec" -o -newer "$enc" \) -print -quit)" ]; then
        return
    fi
    build_one "$PACKAGE"
}

[ $# -ge 1 ] || usage
cmd="$1"
shift
case "$cmd" in
build)
    for pkg in $(packages); do build_one "$pkg"; done
    ;;
runtime)
    test_runtime
    ;;
test)
    test_runtime
    for pkg in $(packages); do
        m="$(manifest "$pkg")"
        echo "== $pkg: clippy" >&2
        cargo clippy --quiet --manifest-path "$m" --all-targets -- -D warnings
        echo "== $pkg: clippy (core only)" >&2
        CARGO_TARGET_DIR="$CORE_TARGET_DIR" cargo clippy --quiet --manifest-path "$m" --lib --no-default-features -- -D warnings
        echo "== $pkg: test" >&2
        cargo test --quiet --manifest-path "$m"
        echo "== $pkg: build (core only, --no-default-features)" >&2
        CARGO_TARGET_DIR="$CORE_TARGET_DIR" cargo build --quiet --manifest-path "$m" --lib --no-default-features
    done
    ;;
decode)
    [ $# -ge 1 ] || usage
    file="$1"
    shift
    ensure_built
    exec "$CARGO_TARGET_DIR/release/$PACKAGE-decode" "$@" "$file"
    ;;
encode)
    ensure_built
    exec "$CARGO_TARGET_DIR/release/$PACKAGE-encode" "$@"
    ;;
example)
    # cargo run (not the binary under target/): both crates' examples are named getting_started.
    exec cargo run --release --quiet --manifest-path "$(manifest "$PACKAGE")" --example getting_started -- "$@"
    ;;
*)
    usage
    ;;
esac
