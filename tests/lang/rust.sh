#!/usr/bin/env bash
# Build, test and run the generated Rust crates.
#   tests/lang/rust.sh build                      cargo build --release of every crate under generated/rust/
#   tests/lang/rust.sh test                       the runtime in place (as `runtime`), then clippy
#                                                 -D warnings, cargo test, a core-only
#                                                 (--no-default-features) build, clippy of the core
#                                                 with one set (`set-*`), `package` and
#                                                 `consumer`, for every crate; the application
#                                                 programs formatted and lint-free
#   tests/lang/rust.sh package                    cargo package of every crate: the .crate holds
#                                                 exactly the crate's files, the manifest's metadata
#                                                 is complete; the smallest crate is verified (built
#                                                 from its .crate, offline)
#   tests/lang/rust.sh publish                    cargo publish --dry-run of every crate (needs the
#                                                 crates.io index; make test-release, CI)
#   tests/lang/rust.sh consumer                   the out-of-tree consumers of tests/lang/rust_consumer/
#                                                 (path dependency, default features and
#                                                 default-features = false) built and run
#   tests/lang/rust.sh msrv                       (CI) the smallest crate built and tested with the
#                                                 toolchain of its rust-version (rustup)
#   tests/lang/rust.sh embedded                   (CI) every crate without default features in a
#                                                 firmware image for thumbv7em-none-eabihf (the
#                                                 no_std consumer, no allocator); prints its size;
#                                                 fails when the image that decodes one set (the
#                                                 first data set's feature) is 32 kB or more
#   tests/lang/rust.sh runtime                    the runtime where it is edited, generator/targets/rust/
#                                                 runtime/ (no regeneration of generated/ needed):
#                                                 rustfmt --check, then for each framing of the test
#                                                 protocol rendered from tests/runtime_specs/: clippy,
#                                                 rustdoc and the runtime's tests (runtime/tests/)
#   tests/lang/rust.sh decode FILE [--device ID]  run <package>-decode (FILE may be -)
#   tests/lang/rust.sh encode                     run <package>-encode (stdin -> stdout)
#   tests/lang/rust.sh example FILE               cargo run --example getting_started -- FILE
#   tests/lang/rust.sh configure ADDRESS [COUNT]  cargo run --features serial --example configure_and_stream -- ADDRESS [COUNT]
#   tests/lang/rust.sh session --connect ADDRESS ...  run <package>-session, the session tool
#                                                 (docs/conformance.md section 8)
#   tests/lang/rust.sh app NAME [ARGS...]         build and run the application program NAME of
#                                                 tests/apps/rust/ (tests/apps/README.md; no ARGS:
#                                                 its usage, exit 2)
# The crate for decode/encode/example/configure is $RUST_PACKAGE (default: mipcodec). Works from any directory.
# Target directories live under build/rust/ (never in generated/); cargo output goes to stderr.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
PACKAGE="${RUST_PACKAGE:-mipcodec}"
export CARGO_TARGET_DIR="$ROOT/build/rust/target"
# A separate target dir for the core-only build, so feature changes do not force rebuilds.
CORE_TARGET_DIR="$ROOT/build/rust/target-core"
# The runtime (src/, copied into every crate) and its unit tests (tests/, with the manifest
# Cargo.toml that runs them against the rendered test protocol); a target dir per framing.
RUNTIME="$ROOT/generator/targets/rust/runtime"
RUNTIME_TARGET_DIR="$ROOT/build/rust/target-runtime"
if [ -x "$ROOT/.venv/bin/python" ]; then PY="$ROOT/.venv/bin/python"; else PY="$(command -v python3)"; fi

# cargo package's output and the out-of-tree consumers (copied from CONSUMER_SRC).
PACKAGE_TARGET_DIR="$ROOT/build/rust/target-package"
CONSUMER_SRC="$ROOT/tests/lang/rust_consumer"
CONSUMER_DIR="$ROOT/build/rust/consumer"
# The firmware target of `embedded` (Cortex-M4F), and the MSRV build of `msrv`.
EMBEDDED_TARGET=thumbv7em-none-eabihf
EMBEDDED_TARGET_DIR="$ROOT/build/rust/target-embedded"
MSRV_TARGET_DIR="$ROOT/build/rust/target-msrv"
# The application programs (a cargo project with a path dependency on mipcodec, `serial`).
APPS="$ROOT/tests/apps/rust"

usage() {
    echo "usage: tests/lang/rust.sh build | test | runtime | package | publish | consumer | msrv | embedded | decode FILE [--device ID] | encode | session --connect ADDRESS ... | example FILE | configure ADDRESS [COUNT] | app NAME [ARGS...]" >&2
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

# The runtime where it is edited, formatted as the generator formats what it copies, then against
# the test protocol `testproto` rendered by the Rust back end from tests/runtime_specs/ (framings
# a and b; docs/runtime-contract.md) into build/runtime_specs/<framing>/rust/testproto/: that crate
# (the runtime's files copied in) lint-free with and without std and documented, and the runtime's
# unit tests (runtime/tests/, manifest runtime/Cargo.toml copied to build/runtime_specs/<framing>/
# tests-rust/) run against it. No hand-written stand-ins of generated modules.
test_runtime() {
    local framing out crate tests target
    echo "== runtime: rustfmt --check" >&2
    find "$RUNTIME" -name '*.rs' -print0 | xargs -0 rustfmt --check --edition 2021
    for framing in a b; do
        out="$(cd "$ROOT" && "$PY" -m tests.runtime_specs.render rust "$framing")"
        crate="$out/rust/testproto/Cargo.toml"
        tests="$out/tests-rust"
        target="$RUNTIME_TARGET_DIR-$framing"
        mkdir -p "$tests"
        cmp -s "$RUNTIME/Cargo.toml" "$tests/Cargo.toml" || cp "$RUNTIME/Cargo.toml" "$tests/Cargo.toml"
        echo "== runtime, framing $framing: clippy" >&2
        CARGO_TARGET_DIR="$target" cargo clippy --quiet --manifest-path "$crate" --all-targets -- -D warnings
        echo "== runtime, framing $framing: clippy (core only)" >&2
        CARGO_TARGET_DIR="$target" cargo clippy --quiet --manifest-path "$crate" --lib --no-default-features -- -D warnings
        echo "== runtime, framing $framing: doc (warnings are errors)" >&2
        CARGO_TARGET_DIR="$target" RUSTDOCFLAGS="-D warnings" cargo doc --quiet --no-deps --manifest-path "$crate"
        echo "== runtime, framing $framing: the runtime's tests (clippy, test)" >&2
        CARGO_TARGET_DIR="$target" cargo clippy --quiet --manifest-path "$tests/Cargo.toml" --all-targets -- -D warnings
        CARGO_TARGET_DIR="$target" cargo test --quiet --manifest-path "$tests/Cargo.toml"
    done
}

# The crate with the fewest source bytes (verified by `package`, built by `msrv`: one is enough,
# the manifests and the runtime are the same template and files).
smallest_package() {
    local pkg
    for pkg in $(packages); do
        echo "$(du -sk "$ROOT/generated/rust/$pkg/src" | cut -f1) $pkg"
    done | sort -n | head -1 | cut -d' ' -f2
}

# cargo package of every crate. What goes into the .crate (`include` in Cargo.toml) must be
# exactly the crate's files (the files cargo adds itself aside), and cargo warns about nothing
# (the documentation URL is docs.rs's; the project has no repository URL to give).
test_package() {
    local pkg m dir listed expected warnings verify="$(smallest_package)" crate
    for pkg in $(packages); do
        m="$(manifest "$pkg")"
        dir="$ROOT/generated/rust/$pkg"
        echo "== $pkg: cargo package" >&2
        listed="$(CARGO_TARGET_DIR="$PACKAGE_TARGET_DIR" cargo package --list --allow-dirty --offline \
            --manifest-path "$m" 2>/dev/null | grep -v -x -e Cargo.toml.orig -e Cargo.lock -e .cargo_vcs_info.json | sort)"
        expected="$(cd "$dir" && find . -type f ! -path './target/*' ! -name Cargo.lock | sed 's|^\./||' | sort)"
        if [ "$listed" != "$expected" ]; then
            echo "rust.sh package: the .crate of $pkg does not hold exactly the crate's files (< packaged, > on disk):" >&2
            diff <(echo "$listed") <(echo "$expected") >&2 || true
            exit 1
        fi
        if [ "$pkg" = "$verify" ]; then
            warnings="$(CARGO_TARGET_DIR="$PACKAGE_TARGET_DIR" cargo package --quiet --allow-dirty --offline \
                --manifest-path "$m" 2>&1 >/dev/null)"
        else
            warnings="$(CARGO_TARGET_DIR="$PACKAGE_TARGET_DIR" cargo package --quiet --allow-dirty --no-verify \
                --manifest-path "$m" 2>&1 >/dev/null)"
        fi
        warnings="$(grep -E '^(warning|error)' <<<"$warnings" || true)"
        if [ -n "$warnings" ]; then
            echo "rust.sh package: cargo package of $pkg: $warnings" >&2
            exit 1
        fi
        crate="$(ls "$PACKAGE_TARGET_DIR/package/$pkg"-*.crate)"
        # The published manifest carries what crates.io and a vendoring team look for.
        local key
        for key in description license readme documentation rust-version keywords categories; do
            tar -xzOf "$crate" --wildcards "$pkg-*/Cargo.toml" | grep -q "^$key = " || {
                echo "rust.sh package: $crate: Cargo.toml has no $key" >&2
                exit 1
            }
        done
    done
}

# The release check (make test-release, docs/versioning.md "Releasing"): `cargo publish --dry-run`
# of every crate, from a copy outside the git tree (so no --allow-dirty: nothing of the checkout
# is in it), which reads the crates.io index (the `serial` feature's dependencies must exist
# there). The smallest crate is verified (built from its .crate, as crates.io would); the others
# with --no-verify (the same sources; building mipcodec from its .crate takes minutes).
test_publish() {
    local pkg copy out verify="$(smallest_package)" flags tmp
    tmp="$(mktemp -d)"
    trap 'rm -rf "$tmp"' RETURN
    for pkg in $(packages); do
        copy="$tmp/$pkg"
        cp -R "$ROOT/generated/rust/$pkg" "$copy"
        rm -rf "$copy/target" "$copy/Cargo.lock"
        flags=(--no-verify)
        [ "$pkg" = "$verify" ] && flags=()
        echo "== $pkg: cargo publish --dry-run ${flags[*]}" >&2
        if ! out="$(cd "$copy" && CARGO_TARGET_DIR="$ROOT/build/release/rust-target" \
            cargo publish --dry-run ${flags[@]+"${flags[@]}"} 2>&1)"; then
            echo "rust.sh publish: cargo publish --dry-run of $pkg failed:" >&2
            echo "$out" >&2
            exit 1
        fi
        if grep -E '^(warning|error)' <<<"$out" | grep -v -x 'warning: aborting upload due to dry run'; then
            echo "rust.sh publish: cargo publish --dry-run of $pkg warned (above)" >&2
            exit 1
        fi
    done
}

# The cargo feature of the crate's first data set (Cargo.toml: `set-NAME = [...]  # 0xNN, a data
# set`): the set of the one-set firmware image.
one_set_feature() {
    sed -n 's/^\(set-[a-z0-9-]*\) = .*# 0x[0-9A-F]*, a data set$/\1/p' "$(manifest "$1")" | head -1
}

# Copies the consumer projects to build/rust/consumer/PACKAGE/ with the crate's path and name.
setup_consumer() {
    local pkg="$1" dst="$CONSUMER_DIR/$1" part one
    one="$(one_set_feature "$pkg")"
    if [ -z "$one" ]; then
        echo "rust.sh: $(manifest "$pkg") has no feature of a data set (set-NAME = [...]  # 0xNN, a data set)" >&2
        exit 1
    fi
    mkdir -p "$dst"
    for part in app core firmware; do
        rm -rf "${dst:?}/$part"
        cp -R "$CONSUMER_SRC/$part" "$dst/$part"
    done
    find "$dst" -type f \( -name '*.rs' -o -name Cargo.toml \) -exec \
        sed -i -e "s|@CRATE_DIR@|$ROOT/generated/rust/$pkg|" -e "s/@ONE_SET@/$one/" -e "s/\bprotocodec\b/$pkg/g" {} +
}

# Out-of-tree consumers: a std program with default features (run: it checks itself and prints
# two JSON lines), and a no_std library with default-features = false (built, and its tests
# run). They share the target directories of `test`, so the crate is not compiled again.
test_consumer() {
    local pkg dst out
    echo "== consumers: rustfmt --check" >&2
    find "$CONSUMER_SRC" -name '*.rs' -print0 | xargs -0 rustfmt --check --edition 2021
    for pkg in $(packages); do
        dst="$CONSUMER_DIR/$pkg"
        setup_consumer "$pkg"
        echo "== $pkg: consumer (path dependency, default features)" >&2
        out="$(cargo run --quiet --manifest-path "$dst/app/Cargo.toml")"
        if [ "$(wc -l <<<"$out")" != 2 ]; then
            echo "rust.sh consumer: $pkg: want two JSON lines from the consumer, got: $out" >&2
            exit 1
        fi
        echo "== $pkg: consumer (path dependency, default-features = false, no_std)" >&2
        CARGO_TARGET_DIR="$CORE_TARGET_DIR" cargo build --quiet --manifest-path "$dst/core/Cargo.toml"
        CARGO_TARGET_DIR="$CORE_TARGET_DIR" cargo test --quiet --manifest-path "$dst/core/Cargo.toml" >&2
        echo "== $pkg: consumer (no_std, one set in the dispatch: feature $(one_set_feature "$pkg"))" >&2
        CARGO_TARGET_DIR="$CORE_TARGET_DIR-one-set" cargo test --quiet --manifest-path "$dst/core/Cargo.toml" \
            --features one-set >&2
    done
}

# The application programs of tests/apps/rust/ (run by the conformance tests): formatted and
# lint-free like the crate.
test_apps() {
    echo "== apps: rustfmt --check, clippy" >&2
    find "$APPS" -name '*.rs' -print0 | xargs -0 rustfmt --check --edition 2021
    cargo clippy --quiet --locked --manifest-path "$APPS/Cargo.toml" --all-targets -- -D warnings
}

# The minimum supported Rust version (rust-version of Cargo.toml, generator/targets/rust/facts.py):
# the smallest crate with exactly that toolchain, core only and with std, and its tests.
test_msrv() {
    local pkg m version
    pkg="$(smallest_package)"
    m="$(manifest "$pkg")"
    version="$(sed -n 's/^rust-version = "\(.*\)"$/\1/p' "$m")"
    if ! rustup run "$version" cargo --version >/dev/null 2>&1; then
        echo "rust.sh msrv: Rust $version is not installed; run: rustup toolchain install $version --profile minimal (or tools/bootstrap --ci)" >&2
        exit 1
    fi
    # Cargo before 1.68 reads the crates.io index only through git (github.com), even for an
    # optional dependency that no build uses: the crate is built from a copy whose manifest has
    # the `serial` feature (serialport and nix, std only) taken out. (serialport =4.2.2 with the `serial`
    # feature builds with Rust 1.65 too; checked by hand, see README.md of the crate.)
    local copy="$ROOT/build/rust/msrv-crate/$pkg"
    rm -rf "$copy"
    mkdir -p "$(dirname "$copy")"
    cp -R "$ROOT/generated/rust/$pkg" "$copy"
    rm -f "$copy/Cargo.lock"
    sed -i -e '/^serial = /d' -e '/^serialport = /d' -e '/^nix = /d' -e '/^\[dependencies\]$/d' \
        -e "/^\[target.'cfg(unix)'.dependencies\]$/d" "$copy/Cargo.toml"
    m="$copy/Cargo.toml"
    echo "== $pkg: Rust $version (rust-version): build --no-default-features, build, test" >&2
    CARGO_TARGET_DIR="$MSRV_TARGET_DIR" cargo "+$version" build --quiet --manifest-path "$m" --lib --no-default-features
    CARGO_TARGET_DIR="$MSRV_TARGET_DIR" cargo "+$version" test --quiet --manifest-path "$m" >&2
}

# Sizes (text, data, bss) of ELF images, with the first size tool found.
image_size() {
    local tool
    for tool in llvm-size llvm-size-14 arm-none-eabi-size size; do
        if command -v "$tool" >/dev/null; then
            "$tool" "$@"
            return
        fi
    done
    echo "(no size tool: install binutils or llvm)"
}

# The limit of the one-set firmware image (text + data, bytes; issue 38): the parser and one
# set's decode_field.
ONE_SET_LIMIT=32768

# The bytes of flash an ELF image takes (text + data, as `size` counts them): the sizes of its
# allocated sections that hold bytes in the file (SHF_ALLOC, not SHT_NOBITS), read from the
# section headers with Python, so that the check needs no size tool.
flash_bytes() {
    "$PY" - "$1" <<'PYEOF'
import struct, sys
data = open(sys.argv[1], "rb").read()
if data[:4] != b"\x7fELF":
    sys.exit(f"rust.sh embedded: {sys.argv[1]}: not an ELF file")
wide, order = data[4] == 2, "<" if data[5] == 1 else ">"
if wide:
    shoff, = struct.unpack_from(order + "Q", data, 0x28)
    shentsize, shnum = struct.unpack_from(order + "HH", data, 0x3A)
else:
    shoff, = struct.unpack_from(order + "I", data, 0x20)
    shentsize, shnum = struct.unpack_from(order + "HH", data, 0x2E)
total = 0
for i in range(shnum):
    at = shoff + i * shentsize
    if wide:
        sh_type, sh_flags = struct.unpack_from(order + "IQ", data, at + 4)
        sh_size, = struct.unpack_from(order + "Q", data, at + 0x20)
    else:
        sh_type, sh_flags = struct.unpack_from(order + "II", data, at + 4)
        sh_size, = struct.unpack_from(order + "I", data, at + 0x14)
    if sh_flags & 0x2 and sh_type != 8:  # SHF_ALLOC, not SHT_NOBITS
        total += sh_size
print(total)
PYEOF
}

# Every crate without std for a Cortex-M4F, and the firmware consumer linked without an allocator:
# the parser image, the decode image (every set in the dispatch) and the decode image with one
# set (its cargo feature), whose size must stay under ONE_SET_LIMIT.
test_embedded() {
    local pkg dst image one one_image size
    if command -v rustup >/dev/null && ! rustup target list --installed | grep -qx "$EMBEDDED_TARGET"; then
        echo "rust.sh embedded: the $EMBEDDED_TARGET target is not installed; run: rustup target add $EMBEDDED_TARGET (or tools/bootstrap --ci)" >&2
        exit 1
    fi
    for pkg in $(packages); do
        # The crate is built with default-features = false for the target as the image's dependency.
        echo "== $pkg: --no-default-features for $EMBEDDED_TARGET: firmware image (no allocator, opt-level s, LTO)" >&2
        dst="$CONSUMER_DIR/$pkg"
        setup_consumer "$pkg"
        CARGO_TARGET_DIR="$EMBEDDED_TARGET_DIR/firmware-$pkg" cargo build --quiet --release \
            --manifest-path "$dst/firmware/Cargo.toml" --target "$EMBEDDED_TARGET"
        image="$EMBEDDED_TARGET_DIR/firmware-$pkg/$EMBEDDED_TARGET/release"
        echo "$pkg firmware images ($EMBEDDED_TARGET): parser = stream parser, field iterator, packet builder;"
        echo "  decode = the same and decode_field, which links the decoder of every field"
        one="$(one_set_feature "$pkg")"
        echo "== $pkg: the decode image with one set in the dispatch (feature $one)" >&2
        CARGO_TARGET_DIR="$EMBEDDED_TARGET_DIR/firmware-$pkg-one-set" cargo build --quiet --release \
            --manifest-path "$dst/firmware/Cargo.toml" --target "$EMBEDDED_TARGET" --features one-set --bin decode
        one_image="$image/decode-$one"
        cp "$EMBEDDED_TARGET_DIR/firmware-$pkg-one-set/$EMBEDDED_TARGET/release/decode" "$one_image"
        echo "  decode-$one = decode with the feature $one: decode_field links that set's decoders only"
        image_size "$image/parser" "$image/decode" "$one_image"
        # text + data of the ELF (the flash the image takes): the sizes of its allocated sections
        # that hold bytes in the file, from the section headers.
        size="$(flash_bytes "$one_image")"
        echo "  decode-$one: $size bytes of flash (limit $ONE_SET_LIMIT)"
        if [ "$size" -ge "$ONE_SET_LIMIT" ]; then
            echo "rust.sh embedded: $pkg: the one-set firmware image (feature $one) is $size bytes, not under $ONE_SET_LIMIT" >&2
            exit 1
        fi
    done
}

build_one() {
    # The tools with the `serial` feature: the session tool opens serial ports (and pseudo-terminals).
    cargo build --release --quiet --manifest-path "$(manifest "$1")" --bins --features serial >&2
}

# Build the tools unless all exist and are newer than every file of the crate.
ensure_built() {
    local dec="$CARGO_TARGET_DIR/release/$PACKAGE-decode" enc="$CARGO_TARGET_DIR/release/$PACKAGE-encode"
    local ses="$CARGO_TARGET_DIR/release/$PACKAGE-session"
    if [ -x "$dec" ] && [ -x "$enc" ] && [ -x "$ses" ] && [ -f "$(manifest "$PACKAGE")" ] \
        && [ -z "$(find "$ROOT/generated/rust/$PACKAGE" -type f \( -newer "$dec" -o -newer "$enc" -o -newer "$ses" \) -print -quit)" ]; then
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
package)
    test_package
    ;;
publish)
    test_publish
    ;;
consumer)
    test_consumer
    ;;
msrv)
    test_msrv
    ;;
embedded)
    test_embedded
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
        echo "== $pkg: clippy (core only, one set in the dispatch: --features $(one_set_feature "$pkg"))" >&2
        CARGO_TARGET_DIR="$CORE_TARGET_DIR-one-set" cargo clippy --quiet --manifest-path "$m" --lib \
            --no-default-features --features "$(one_set_feature "$pkg")" -- -D warnings
    done
    test_package
    test_consumer
    test_apps
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
session)
    ensure_built
    exec "$CARGO_TARGET_DIR/release/$PACKAGE-session" "$@"
    ;;
configure)
    # With the `serial` feature: ADDRESS may be a serial port or a pseudo-terminal (the simulator's).
    exec cargo run --release --quiet --manifest-path "$(manifest "$PACKAGE")" --features serial --example configure_and_stream -- "$@"
    ;;
app)
    [ $# -ge 1 ] || usage
    name="$1"
    shift
    if [ ! -f "$APPS/$name.rs" ]; then
        echo "rust.sh app: no application program $name in tests/apps/rust/" >&2
        exit 2
    fi
    # Built in the tools' target directory, so serialport is not compiled again (mipcodec is, once:
    # cargo hashes a path dependency relative to the workspace root); --locked: the committed
    # Cargo.lock (lockfile version 3, as the crate's rust-version reads it).
    cargo build --release --quiet --locked --manifest-path "$APPS/Cargo.toml" --bin "$name" >&2
    exec "$CARGO_TARGET_DIR/release/$name" "$@"
    ;;
example)
    # cargo run (not the binary under target/): both crates' examples are named getting_started.
    # With the tools' features (`serial`), so the crate built for the tools is the one it links
    # (the example uses none of it; other features would compile the crate once more).
    exec cargo run --release --quiet --manifest-path "$(manifest "$PACKAGE")" --features serial --example getting_started -- "$@"
    ;;
*)
    usage
    ;;
esac
